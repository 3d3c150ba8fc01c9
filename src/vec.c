/* vec.c - the one copy of vec.h's larger operations on a small-flash build (the M0);
 * elsewhere they are inline and this file is empty.
 * See LICENSE for copyright and licence. */
#define VEC_BODIES
#include "vec.h"

/* ISO C wants something in every file. */
typedef int rt_vec_bodies;
