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

int vsnprintf(char *restrict buf, size_t size, const char *restrict fmt, va_list ap)
{
	out_buf o;
	o.buf = buf;
	o.size = size;
	o.used = 0;
	for (; *fmt; fmt++) {
		char digits[12], *d, pad = ' ';
		int width = 0, precision = -1, is_long = 0, n = 0, i;
		uint32_t u, base = 10;
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
			/* long is 32 bits here, as int is. */
			if (*fmt == 'd') {
				long v = is_long ? va_arg(ap, long) : va_arg(ap, int);
				if (v < 0) {
					put(&o, '-');
					width--;
				}
				u = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
			} else {
				u = is_long ? va_arg(ap, unsigned long) : va_arg(ap, unsigned);
				base = *fmt == 'X' ? 16 : 10;
			}
			/* The digits from the last one back. The M0 has no divide, and the
			 * library's would cost flash: u / 10 is the top of u times 2^35 / 10,
			 * rounded up (exact for every 32-bit u). */
			d = digits + sizeof digits;
			do {
				uint32_t q = base == 16 ? u >> 4
						       : (uint32_t)(((uint64_t)u * 0xCCCCCCCDu) >> 35);
				*--d = "0123456789ABCDEF"[u - q * base];
				u = q;
				n++;
			} while (u);
			s = d;
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
