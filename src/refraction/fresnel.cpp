#include "refraction/fresnel.h"

#include <algorithm>
#include <cmath>

namespace rb {

// [snell]
bool snellCosTheta_t(double cosTheta_i, double eta_i, double eta_t, double& cosTheta_t) {
    // [exercise-snell]
    // Exercise 5.1, Snell's law: read ch05-equations.
    // Blank: return false;
    // Snell's law on the sines, sin θt = (η_i/η_t) sin θi, squared and written with cosines:
    // cos²θt = 1 − η²(1 − cos²θi) = (1 − η²) + η² cos²θi. The second form keeps the digits of a
    // grazing cos θi, which 1 − cos²θi would round away.
    cosTheta_i = std::clamp(cosTheta_i, 0.0, 1.0);
    const double eta = eta_i / eta_t;
    const double cos2Theta_t = (1.0 - eta * eta) + eta * eta * (cosTheta_i * cosTheta_i);
    // Beyond the critical angle no refracted ray exists: total internal reflection.
    if (cos2Theta_t < 0.0) return false;
    cosTheta_t = std::sqrt(cos2Theta_t);
    return true;
    // [exercise-snell]
}
// [snell]

// [fresnel-exact]
FresnelTerms fresnelDielectricTerms(double cosTheta_i, double eta_i, double eta_t) {
    // [exercise-fresnel]
    // Exercise 5.2, the exact Fresnel equations: read ch05-equations.
    // Blank: return FresnelTerms{};
    FresnelTerms f;  // starts as total reflection
    cosTheta_i = std::clamp(cosTheta_i, 0.0, 1.0);
    // The same index on both sides is no interface at all. Handling it here also avoids 0/0
    // at grazing incidence, where both cosines vanish.
    if (eta_i == eta_t) {
        f.Rs = f.Rp = 0.0;
        f.Ts = f.Tp = 1.0;
        f.cosTheta_t = cosTheta_i;
        return f;
    }
    double cosTheta_t = 0.0;
    if (!snellCosTheta_t(cosTheta_i, eta_i, eta_t, cosTheta_t)) {
        f.totalInternalReflection = true;
        return f;
    }
    f.cosTheta_t = cosTheta_t;
    // The Fresnel equations for the s- and p-polarised amplitudes. Unpolarised light carries
    // equal power in both, so its reflectance is the mean of their squares (reflectance()).
    const double sNear = eta_i * cosTheta_i, sFar = eta_t * cosTheta_t;
    const double pNear = eta_t * cosTheta_i, pFar = eta_i * cosTheta_t;
    const double r_s = (sNear - sFar) / (sNear + sFar);
    const double r_p = (pNear - pFar) / (pNear + pFar);
    f.Rs = r_s * r_s;
    f.Rp = r_p * r_p;
    // Transmitted power T = (η_t cos θt)/(η_i cos θi) · t², with t_s = 2 η_i cos θi/(sNear + sFar)
    // and t_p = 2 η_i cos θi/(pNear + pFar); multiplied out, so it has no 1/cos θi to blow up
    // at grazing incidence. Source: E. Hecht, Optics, §4.6 (the Fresnel equations;
    // reflectance and transmittance).
    const double fourProduct = 4.0 * eta_i * cosTheta_i * eta_t * cosTheta_t;
    f.Ts = fourProduct / ((sNear + sFar) * (sNear + sFar));
    f.Tp = fourProduct / ((pNear + pFar) * (pNear + pFar));
    return f;
    // [exercise-fresnel]
}

double fresnelExact(double cosTheta_i, double eta_i, double eta_t) {
    // The renderer's exact reflectance is the record's: one formula for the tests and the
    // images.
    return fresnelDielectricTerms(cosTheta_i, eta_i, eta_t).reflectance();
}
// [fresnel-exact]

// [fresnel-schlick]
double fresnelSchlick(double cosTheta_i, double eta_i, double eta_t) {
    // The same index on both sides is no surface; the polynomial alone would still reflect
    // (1 − cos θ)^5 there, up to everything at grazing incidence.
    if (eta_i == eta_t) return 0.0;
    // Reflectance at normal incidence: R0 = ((η_i − η_t)/(η_i + η_t))².
    const double r = (eta_i - eta_t) / (eta_i + eta_t);
    const double R0 = r * r;
    double cosTheta = std::clamp(cosTheta_i, 0.0, 1.0);
    if (eta_i > eta_t) {
        // Going out into a thinner medium the curve must be taken at the larger angle, the
        // one outside; with cos θi it would miss total internal reflection entirely.
        // Source: B. de Greve, "Reflections and Refractions in Ray Tracing" (2006), §4.
        double cosTheta_t;
        if (!snellCosTheta_t(cosTheta, eta_i, eta_t, cosTheta_t)) return 1.0;
        cosTheta = cosTheta_t;
    }
    // Schlick's polynomial. Source: C. Schlick, "An Inexpensive BRDF Model for
    // Physically-based Rendering", Computer Graphics Forum 13(3), 1994, eq. 24.
    const double m = 1.0 - cosTheta;
    const double m2 = m * m;
    return R0 + (1.0 - R0) * m2 * m2 * m;
}
// [fresnel-schlick]

}  // namespace rb
