/* semihost.h - the microcontroller's link to the host: ARM semihosting calls, the few
 * rt needs (files, standard streams, command line, exit status). Under qemu-system-arm
 * they need `-semihosting-config enable=on,target=native`.
 * See LICENSE for copyright and licence. */
#ifndef RT_SEMIHOST_H
#define RT_SEMIHOST_H

#include <stddef.h>

enum { SEMIHOST_READ_BINARY = 1, SEMIHOST_WRITE = 4, SEMIHOST_APPEND = 8 };

/* Opens a host file; ":tt" with SEMIHOST_WRITE is standard output, with SEMIHOST_APPEND
 * standard error. Returns a handle, or -1. */
int semihost_open(const char *name, int mode);
int semihost_close(int handle);
/* Reads up to n bytes; returns how many were read (0 at the end), or -1 on error. */
int semihost_read(int handle, void *buf, size_t n);
/* Writes all n bytes; returns 1 on success. */
int semihost_write(int handle, const void *buf, size_t n);
/* The command line qemu was given (`arg=` items joined by spaces) into buf; 1 if ok. */
int semihost_command_line(char *buf, size_t size);
/* Ends the program with this exit status; qemu exits with it. */
void semihost_exit(int status);

#endif
