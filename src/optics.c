/* optics.c - the geometric optics the tracer needs at a surface.
 * See LICENSE for copyright and licence. */
#include "optics.h"

/* Apart (RT_APART): 20 bytes less M0 flash than inlined into the tracer. */
RT_APART dir3 optics_reflect(dir3 d, dir3 n)
{
	return optics_reflect_at(d, n, dir_dot(d, n));
}

dir3 optics_reflect_at(dir3 d, dir3 n, unit c)
{
	/* -2 (d.n) as a sum: the same number in floating point, and saturating in Q2.30,
	 * which holds -2 but not 2 (an LSB off at normal incidence). */
	return dir_madd_unit(d, unit_add(-c, -c), n);
}

int optics_refract(dir3 d, dir3 n, real eta, dir3 *t)
{
	unit cos_i = -dir_dot(d, n);
	if (REAL_SATURATES) {
		/* Q2.30 stops short of 2, and eta d reaches eta: past 2 on leaving a dense
		 * medium. The same t in tangential form keeps every term within unit length:
		 * the tangent d + cos_i n (length sin_i) times eta is the refracted tangent
		 * (length sin_t), and t = eta (d + cos_i n) - cos_t n with cos_t^2 = k =
		 * 1 - eta^2 sin_i^2. The refracted tangent is made only without total internal
		 * reflection: then it is within unit length, and its components cannot
		 * saturate. */
		dir3 tangent = dir_madd_unit(d, cos_i, n), across;
		unit k = UNIT_C(1.0) - unit_scale(unit_scale(dir_dot(tangent, tangent), eta), eta);
		if (!(k > UNIT_C(0.0)))
			return 0;
		across = dir_make(unit_scale(tangent.x, eta), unit_scale(tangent.y, eta),
				  unit_scale(tangent.z, eta));
		*t = dir_madd_unit(across, -unit_sqrt(k), n);
		return 1;
	}
	real k = REAL_C(1.0) - real_mul(real_mul(eta, eta), REAL_C(1.0) - real_mul(cos_i, cos_i));
	if (!(k > REAL_C(0.0)))
		return 0;
	/* t = eta d + (eta cos_i - sqrt k) n */
	*t = dir_make(real_mul(d.x, eta), real_mul(d.y, eta), real_mul(d.z, eta));
	*t = dir_madd_unit(*t, real_mul(eta, cos_i) - real_sqrt(k), n);
	return 1;
}

real optics_fresnel(unit cosine, real eta)
{
	real cos_i = unit_to_real(cosine), sin2_t, cos_t, r_par, r_perp;
	cos_i = real_min(real_max(cos_i, REAL_C(0.0)), REAL_C(1.0));
	sin2_t = real_mul(real_mul(eta, eta), REAL_C(1.0) - real_mul(cos_i, cos_i));
	if (sin2_t >= REAL_C(1.0))
		return REAL_C(1.0);
	cos_t = real_sqrt(REAL_C(1.0) - sin2_t);
	/* Amplitude ratios for light polarised parallel and perpendicular to the plane of
	 * incidence, with eta = n1 / n2 divided through. */
	r_par = real_div(cos_i - real_mul(eta, cos_t), cos_i + real_mul(eta, cos_t));
	r_perp = real_div(real_mul(eta, cos_i) - cos_t, real_mul(eta, cos_i) + cos_t);
	return real_mul(REAL_C(0.5), real_mul(r_par, r_par) + real_mul(r_perp, r_perp));
}

real optics_beer(real absorb, real distance)
{
	real pass;
	if (!(distance > REAL_C(0.0)) || absorb == REAL_C(0.0))
		return REAL_C(1.0);
	pass = real_exp(-real_mul(absorb, distance));
	return pass < REAL_C(1e-30) ? REAL_C(0.0) : pass;
}

/* c^n for a Phong highlight (0 < c <= 1). A whole exponent up to 4096, as scenes write
 * them, goes by squaring: a dozen products instead of pow's logarithm and exponential,
 * which took 15 % of a small scene's time; its few roundings are of the size of pow's
 * own in each type. A power below 2^-64 is 0 (it is nothing beside a colour, and its
 * subnormal products would be slow); so is c^n for an exponent of 16 or more with a
 * fraction whose whole part's power is (c^n is no larger): SPD mount's glass, shine
 * 101.148, is lit so wherever c is below 0.65, most of its calls to pow. Q16.16 keeps
 * its fixed_pow. */
real optics_highlight(real c, real n)
{
	real result = REAL_C(1.0), base = c;
	int e, whole;
	if (REAL_FIXED || !(n >= REAL_C(0.0) && n <= REAL_C(4096.0)))
		return real_pow(c, n);
	whole = n == real_from_int(real_to_int(n));
	/* Below 16 a whole part's power reaches 2^-64 only for c under 2^-4: rarely worth
	 * its products. */
	if (!whole && n < REAL_C(16.0))
		return real_pow(c, n);
	for (e = real_to_int(n); e; e >>= 1) {
		if (e & 1)
			result = real_mul(result, base);
		base = real_mul(base, base);
		if (result < REAL_C(5.421010862427522e-20) || base < REAL_C(5.421010862427522e-20)) {
			if (e > 1 || result < REAL_C(5.421010862427522e-20))
				return REAL_C(0.0);
			break;
		}
	}
	return whole ? result : real_pow(c, n);
}

#if !REAL_FIXED
/* The least cosine c whose highlight c^n optics_highlight does not make 0, or 0: below
 * it the highlight is 0 without the products (SPD mount's glass: c below 0.65, most of
 * the cosines its highlights are asked for, each a dozen products and as many branches
 * taken as the cosine says). Where optics_highlight squares (a whole exponent, or 16 or
 * more), whether it gives 0 early only grows as c falls: each base and product is no
 * larger for a smaller c (rounding keeps the order), and a step that falls below 2^-64
 * for c does so at that step or before for any smaller c, where it gives 0 too (the one
 * exception, the last step's base, ends the loop for both). So halving the interval
 * between a cosine that gives 0 and one that does not finds the least one exactly, to
 * adjacent numbers of the type. pow's own path (a fraction below 16) keeps no floor, nor
 * does an exponent below 1 (c^0 is 1). */
real optics_highlight_floor(real shine)
{
	real zero = REAL_C(1.0) / REAL_C(36893488147419103232.0), lit = REAL_C(1.0);
	int i;
	if (!(shine >= REAL_C(1.0) && shine <= REAL_C(4096.0)) ||
	    (shine != real_from_int(real_to_int(shine)) && shine < REAL_C(16.0)))
		return REAL_C(0.0);
	/* 2^-65 gives 0 for every exponent of 1 or more: its first power is below the
	 * cut-off. Halving reaches adjacent numbers within the mantissa's bits and the 64
	 * binades between, well inside the 256 steps allowed. */
	if (optics_highlight(zero, shine) != REAL_C(0.0) ||
	    optics_highlight(lit, shine) == REAL_C(0.0))
		return REAL_C(0.0);
	for (i = 0; i < 256; i++) {
		real mid = zero + (lit - zero) / 2;
		if (!(mid > zero && mid < lit))
			return lit;
		if (optics_highlight(mid, shine) == REAL_C(0.0))
			zero = mid;
		else
			lit = mid;
	}
	return REAL_C(0.0);
}
#endif
