/* semihost.c - ARM semihosting: an operation number in r0, a pointer to its arguments in
 * r1, then `bkpt 0xab`; the debugger (here qemu) does the work and answers in r0.
 * See LICENSE for copyright and licence. */
#include "semihost.h"

#include <stdint.h>
#include <string.h>

enum {
	SYS_OPEN = 0x01,
	SYS_CLOSE = 0x02,
	SYS_WRITE = 0x05,
	SYS_READ = 0x06,
	SYS_GET_CMDLINE = 0x15,
	SYS_EXIT_EXTENDED = 0x20
};

#define ADP_STOPPED_APPLICATION_EXIT 0x20026 /* the reason code of a normal exit */

static int call(int op, void *args)
{
	/* r0 is in and out: the answer comes back in the register the operation went in. */
	register int r0 __asm__("r0") = op;
	register void *r1 __asm__("r1") = args;
	__asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
	return r0;
}

int semihost_open(const char *name, int mode)
{
	uintptr_t args[3];
	args[0] = (uintptr_t)name;
	args[1] = (uintptr_t)mode;
	args[2] = strlen(name);
	return call(SYS_OPEN, args);
}

int semihost_close(int handle)
{
	uintptr_t args[1];
	args[0] = (uintptr_t)handle;
	return call(SYS_CLOSE, args);
}

int semihost_read(int handle, void *buf, size_t n)
{
	uintptr_t args[3];
	int left;
	args[0] = (uintptr_t)handle;
	args[1] = (uintptr_t)buf;
	args[2] = n;
	/* The answer is the number of bytes NOT read. */
	left = call(SYS_READ, args);
	return left < 0 || (size_t)left > n ? -1 : (int)(n - (size_t)left);
}

int semihost_write(int handle, const void *buf, size_t n)
{
	uintptr_t args[3];
	args[0] = (uintptr_t)handle;
	args[1] = (uintptr_t)buf;
	args[2] = n;
	/* The answer is the number of bytes NOT written. */
	return call(SYS_WRITE, args) == 0;
}

int semihost_command_line(char *buf, size_t size)
{
	uintptr_t args[2];
	args[0] = (uintptr_t)buf;
	args[1] = size - 1;
	if (call(SYS_GET_CMDLINE, args) != 0)
		return 0;
	buf[args[1] < size ? args[1] : size - 1] = '\0';
	return 1;
}

void semihost_exit(int status)
{
	uintptr_t args[2];
	args[0] = ADP_STOPPED_APPLICATION_EXIT;
	args[1] = (uintptr_t)status;
	call(SYS_EXIT_EXTENDED, args);
	for (;;) {
	}
}
