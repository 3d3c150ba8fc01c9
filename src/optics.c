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
