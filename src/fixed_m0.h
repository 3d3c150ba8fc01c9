/* fixed_m0.h - the Cortex-M0's arithmetic kernels in Thumb-1 assembly: a saturating add,
 * 32 x 32 -> 64-bit products from four 16 x 16 ones, a 64-bit add, and the steps of a
 * 64 / 32 division. fixed_narrow.h includes it only where GCC builds for an ARMv6-M
 * core (FIXED_ASM); every other build has the C forms there, with the same results
 * (tests/test_fixed.c checks them on the host and under qemu).
 * GCC hands Thumb-1 inline assembly to the assembler in the old divided syntax: these
 * lines are in unified syntax.
 * See LICENSE for copyright and licence. */
#ifndef RT_FIXED_M0_H
#define RT_FIXED_M0_H

RT_INLINE int32_t fixed_add(int32_t a, int32_t b)
{
	int32_t sum, sign;
	__asm__(".syntax unified\n\t"
		"adds %[sum], %[a], %[b]\n\t"
		"bvs 1f\n\t"
		"subs %[sign], %[sum], #1\n\t" /* overflows for sum = -2^31 only */
		"bvc 2f\n\t"
		"adds %[sum], #1\n\t" /* -2^31 + 1 = -INT32_MAX */
		"b 2f\n"
		"1:\n\t"
		"asrs %[sign], %[b], #31\n\t" /* the exact sum's sign: 0 or -1 */
		"movs %[sum], #1\n\t"
		"lsls %[sum], %[sum], #31\n\t"
		"subs %[sum], #1\n\t"            /* INT32_MAX */
		"eors %[sum], %[sign]\n\t"       /* or -2^31 */
		"subs %[sum], %[sum], %[sign]\n" /* or -2^31 + 1 */
		"2:"
		: [sum] "=&l"(sum), [sign] "=&l"(sign)
		: [a] "l"(a), [b] "l"(b)
		: "cc");
	return sum;
}

RT_INLINE void fixed_umul64_parts(uint32_t a, uint32_t b, uint32_t *low, uint32_t *high)
{
	uint32_t al, bl, product;
	__asm__(".syntax unified\n\t"
		"uxth %[al], %[a]\n\t"
		"uxth %[bl], %[b]\n\t"
		"lsrs %[a], %[a], #16\n\t"
		"lsrs %[b], %[b], #16\n\t"
		"movs %[p], %[al]\n\t"
		"muls %[p], %[bl]\n\t" /* al bl */
		"muls %[al], %[b]\n\t" /* al bh */
		"muls %[bl], %[a]\n\t" /* ah bl */
		"muls %[b], %[a]\n\t"  /* ah bh */
		"lsls %[a], %[al], #16\n\t"
		"lsrs %[al], %[al], #16\n\t"
		"adds %[p], %[a]\n\t"
		"adcs %[b], %[al]\n\t"
		"lsls %[a], %[bl], #16\n\t"
		"lsrs %[bl], %[bl], #16\n\t"
		"adds %[p], %[a]\n\t"
		"adcs %[b], %[bl]"
		: [a] "+l"(a), [b] "+l"(b), [al] "=&l"(al), [bl] "=&l"(bl), [p] "=&l"(product)
		:
		: "cc");
	*low = product;
	*high = b;
}

/* The signed form of fixed_umul64_parts: the same steps, with arithmetic shifts where
 * that one shifts logically (three instructions differ; one routine for both would cost
 * the M0 a sign fix-up per product). */
RT_INLINE void fixed_wide_mul_parts(int32_t a, int32_t b, uint32_t *low, int32_t *high)
{
	uint32_t al, bl, product;
	/* a and b become their high halves; the four products, then each cross product
	 * added at bit 16 with its carry. */
	__asm__(".syntax unified\n\t"
		"uxth %[al], %[a]\n\t"
		"uxth %[bl], %[b]\n\t"
		"asrs %[a], %[a], #16\n\t"
		"asrs %[b], %[b], #16\n\t"
		"movs %[p], %[al]\n\t"
		"muls %[p], %[bl]\n\t" /* al bl */
		"muls %[al], %[b]\n\t" /* al bh */
		"muls %[bl], %[a]\n\t" /* ah bl */
		"muls %[b], %[a]\n\t"  /* ah bh */
		"lsls %[a], %[al], #16\n\t"
		"asrs %[al], %[al], #16\n\t"
		"adds %[p], %[a]\n\t"
		"adcs %[b], %[al]\n\t"
		"lsls %[a], %[bl], #16\n\t"
		"asrs %[bl], %[bl], #16\n\t"
		"adds %[p], %[a]\n\t"
		"adcs %[b], %[bl]"
		: [a] "+l"(a), [b] "+l"(b), [al] "=&l"(al), [bl] "=&l"(bl), [p] "=&l"(product)
		:
		: "cc");
	*low = product;
	*high = b;
}

RT_INLINE void fixed_add_parts(uint32_t *low, int32_t *high, uint32_t add_low,
				   int32_t add_high)
{
	uint32_t l = *low;
	int32_t h = *high;
	__asm__(".syntax unified\n\t"
		"adds %[l], %[al]\n\t"
		"adcs %[h], %[ah]"
		: [l] "+l"(l), [h] "+l"(h)
		: [al] "l"(add_low), [ah] "l"(add_high)
		: "cc");
	*low = l;
	*high = h;
}

/* The quotient steps of fixed_udiv_narrow (16 or 32 of them), four to a pass. */
RT_INLINE void fixed_udiv_steps(uint32_t *low_bits, uint32_t *remainder, uint32_t d,
				     int steps)
{
	uint32_t low = *low_bits, rem = *remainder;
	/* (rem, low) shifts left as one 64-bit number; a carry out of rem means the
	 * remainder passed 2^32 > d. Four steps per pass (16 and 32 are multiples of 4):
	 * the count and its branch once per four quotient bits. Each step's labels 2 and 3
	 * are its own: `2f` and `3f` name the next ones. */
#define FIXED_UDIV_STEP                     \
	"adds %[low], %[low]\n\t"          \
	"adcs %[rem], %[rem]\n\t"          \
	"bcs 2f\n\t"                       \
	"cmp %[rem], %[d]\n\t"             \
	"bcc 3f\n"                          \
	"2:\n\t"                           \
	"subs %[rem], %[d]\n\t"            \
	"adds %[low], #1\n"                 \
	"3:\n\t"
	__asm__(".syntax unified\n"
		"1:\n\t" FIXED_UDIV_STEP FIXED_UDIV_STEP FIXED_UDIV_STEP FIXED_UDIV_STEP
		"subs %[steps], #4\n\t"
		"bne 1b"
		: [low] "+l"(low), [rem] "+l"(rem), [steps] "+l"(steps)
		: [d] "l"(d)
		: "cc");
#undef FIXED_UDIV_STEP
	*low_bits = low;
	*remainder = rem;
}

#endif
