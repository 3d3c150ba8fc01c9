/* quadratic.c - the one copy of quadratic.h's solve_quadratic on a small-flash build
 * (the M0); elsewhere it is inline and this file is empty.
 * See LICENSE for copyright and licence. */
#define QUADRATIC_BODY
#include "quadratic.h"

/* ISO C wants something in every file. */
typedef int rt_quadratic_body;
