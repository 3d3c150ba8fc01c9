/* optics.c - the geometric optics the tracer needs at a surface.
 * See LICENSE for copyright and licence. */
#include "optics.h"

vec3 optics_reflect(vec3 d, vec3 n)
{
	return vec_madd(d, real_mul(-REAL_C(2.0), vec_dot(d, n)), n);
}

int optics_refract(vec3 d, vec3 n, real eta, vec3 *t)
{
	real cos_i = -vec_dot(d, n);
	real k = REAL_C(1.0) - real_mul(real_mul(eta, eta), REAL_C(1.0) - real_mul(cos_i, cos_i));
	if (!(k > REAL_C(0.0)))
		return 0;
	/* t = eta d + (eta cos_i - sqrt k) n */
	*t = vec_madd(vec_scale(d, eta), real_mul(eta, cos_i) - real_sqrt(k), n);
	return 1;
}

real optics_fresnel(real cos_i, real eta)
{
	real sin2_t, cos_t, r_par, r_perp;
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
