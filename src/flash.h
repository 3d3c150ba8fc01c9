/* flash.h - the one place that steers inlining, for the build whose flash is short: a
 * Cortex-M0 (ARMv6-M) with 24 KiB for rt. Everywhere else the compiler decides alone.
 *   RT_SHARED  a function defined in a header: inline on a host; on the M0 one
 *              out-of-line copy, defined in one file (vec.c, fixed.c), since inlined
 *              copies in every file would not fit.
 *   RT_INLINE  inlined on the M0 whatever -Os thinks (a call and its frame would cost
 *              more than the body); an ordinary static inline elsewhere.
 *   RT_APART   kept a function of its own on the M0, whatever link-time optimisation
 *              would inline; each use says what that saves.
 * See LICENSE for copyright and licence. */
#ifndef RT_FLASH_H
#define RT_FLASH_H

#if defined(__ARM_ARCH_6M__)
#define RT_FLASH_SHORT 1
#else
#define RT_FLASH_SHORT 0
#endif

#if RT_FLASH_SHORT && defined(__GNUC__)
#define RT_SHARED __attribute__((noinline))
#define RT_INLINE static inline __attribute__((always_inline))
#define RT_APART __attribute__((noinline))
#elif RT_FLASH_SHORT
#define RT_SHARED
#define RT_INLINE static inline
#define RT_APART
#else
#define RT_SHARED static inline
#define RT_INLINE static inline
#define RT_APART
#endif

#endif
