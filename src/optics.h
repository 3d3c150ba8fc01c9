/* optics.h - reflection, Snell refraction, dielectric Fresnel, Beer-Lambert and the Phong
 * highlight's power.
 * See LICENSE for copyright and licence. */
#ifndef RT_OPTICS_H
#define RT_OPTICS_H

#include "vec.h"

/* Mirror direction of d about the unit normal n; optics_reflect_at takes c = d.n when it
 * is known already (a hit's incidence). */
dir3 optics_reflect(dir3 d, dir3 n);
dir3 optics_reflect_at(dir3 d, dir3 n, unit c);

/* Refracts unit d through unit n (n faces against d) with eta = n1 / n2.
 * Returns 0 on total internal reflection (k = 1 - eta^2 (1 - cos^2) <= 0), else 1 and
 * the unit transmitted direction in *t (numerics.md section 5). */
int optics_refract(dir3 d, dir3 n, real eta, dir3 *t);

/* Exact dielectric Fresnel reflectance for unpolarised light; `cosine` is that of the
 * incident angle, eta = n1 / n2. Returns 1 on total internal reflection. */
real optics_fresnel(unit cosine, real eta);

/* Beer-Lambert transmittance e^(-a d); d < 0 counts as 0 (numerics.md B05) and results
 * below 1e-30 are flushed to 0 so float never goes subnormal (B03). */
real optics_beer(real absorb, real distance);

/* A Phong highlight's power c^n (0 < c <= 1, n the material's shine), by squaring for
 * the exponents scenes write, 0 once below 2^-64. */
real optics_highlight(real c, real n);

#if !REAL_FIXED
/* The least c for which optics_highlight(c, shine) is not 0, or 0 where no such floor is
 * kept: below the floor the power is 0, at and above it not. */
real optics_highlight_floor(real shine);
#endif

#endif
