/* libc.c - the few C library functions rt calls, for a microcontroller with no C library
 * linked: memory and string helpers and an integer-only printf core. Nothing here
 * allocates, and nothing buffers behind the caller's back.
 * See LICENSE for copyright and licence. */
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

void *memset(void *dst, int c, size_t n)
{
	unsigned char *d = dst;
	while (n--)
		*d++ = (unsigned char)c;
	return dst;
}

/* The compiler calls memcpy for some struct copies (vectors, hit records), mostly of
 * whole aligned words: those go a word at a time. */
void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
	unsigned char *d = dst;
	const unsigned char *s = src;
	if (!(((uintptr_t)d | (uintptr_t)s | n) & 3u)) {
		uint32_t *dw = dst;
		const uint32_t *sw = src;
		for (; n; n -= 4)
			*dw++ = *sw++;
		return dst;
	}
	while (n--)
		*d++ = *s++;
	return dst;
}

void *memmove(void *dst, const void *src, size_t n)
{
	unsigned char *d = dst;
	const unsigned char *s = src;
	if (d < s) {
		while (n--)
			*d++ = *s++;
	} else {
		while (n--)
			d[n] = s[n];
	}
	return dst;
}

size_t strlen(const char *s)
{
	size_t n = 0;
	while (s[n])
		n++;
	return n;
}

int strcmp(const char *a, const char *b)
{
	while (*a && *a == *b) {
		a++;
		b++;
	}
	return (unsigned char)*a - (unsigned char)*b;
}

/* ---- formatted output: just what rt's messages and headers use, %s (with a
 * .precision), %d, %u and %X, with the l length and a width, padded with zeros under the
 * 0 flag and with spaces otherwise. Anything else prints as itself. */

typedef struct {
	char *buf;
	size_t size, used; /* used counts every byte, also those that did not fit */
} out_buf;

static void put(out_buf *o, char c)
{
	if (o->used + 1 < o->size)
		o->buf[o->used] = c;
	o->used++;
}

/* Place values of the digits: decimal, then hexadecimal's (after the first 10). */
static const unsigned long places[] = {1000000000ul, 100000000ul, 10000000ul, 1000000ul,
				       100000ul,     10000ul,     1000ul,     100ul,
				       10ul,         1ul,         0x10000000ul, 0x1000000ul,
				       0x100000ul,   0x10000ul,   0x1000ul,   0x100ul,
				       0x10ul,       1ul};

int vsnprintf(char *restrict buf, size_t size, const char *restrict fmt, va_list ap)
{
	out_buf o;
	o.buf = buf;
	o.size = size;
	o.used = 0;
	for (; *fmt; fmt++) {
		char digits[12], pad = ' ';
		int width = 0, precision = -1, is_long = 0, n = 0, i, last;
		unsigned long u;
		const char *s = digits;
		if (*fmt != '%') {
			put(&o, *fmt);
			continue;
		}
		if (*++fmt == '0')
			pad = *fmt++;
		for (; *fmt >= '0' && *fmt <= '9'; fmt++)
			width = width * 10 + (*fmt - '0');
		if (*fmt == '.')
			for (precision = 0, fmt++; *fmt >= '0' && *fmt <= '9'; fmt++)
				precision = precision * 10 + (*fmt - '0');
		if (*fmt == 'l') {
			is_long = 1;
			fmt++;
		}
		if (*fmt == 's') {
			s = va_arg(ap, const char *);
			while (s[n] && (precision < 0 || n < precision))
				n++;
		} else if (*fmt == 'd' || *fmt == 'u' || *fmt == 'X') {
			if (*fmt == 'd') {
				long v = is_long ? va_arg(ap, long) : va_arg(ap, int);
				if (v < 0) {
					put(&o, '-');
					width--;
				}
				u = v < 0 ? 0u - (unsigned long)v : (unsigned long)v;
			} else {
				u = is_long ? va_arg(ap, unsigned long) : va_arg(ap, unsigned);
			}
			/* Each digit by counting down its place value: the M0 has no divide,
			 * and the library's would cost flash. Leading zeros are left out. */
			i = *fmt == 'X' ? 10 : 0;
			last = *fmt == 'X' ? 17 : 9;
			for (; i <= last; i++) {
				int d = 0;
				while (u >= places[i]) {
					u -= places[i];
					d++;
				}
				if (d || n || i == last)
					digits[n++] = "0123456789ABCDEF"[d];
			}
		} else {
			/* %% and anything unknown print as themselves */
			put(&o, *fmt ? *fmt : '%');
			if (!*fmt)
				fmt--;
			continue;
		}
		for (; width > n; width--)
			put(&o, pad);
		for (i = 0; i < n; i++)
			put(&o, s[i]);
	}
	if (size > 0)
		buf[o.used < size ? o.used : size - 1] = '\0';
	return (int)o.used;
}

int snprintf(char *restrict buf, size_t size, const char *restrict fmt, ...)
{
	va_list ap;
	int n;
	va_start(ap, fmt);
	n = vsnprintf(buf, size, fmt, ap);
	va_end(ap);
	return n;
}

int sprintf(char *restrict buf, const char *restrict fmt, ...)
{
	va_list ap;
	int n;
	va_start(ap, fmt);
	n = vsnprintf(buf, (size_t)INT_MAX, fmt, ap);
	va_end(ap);
	return n;
}
