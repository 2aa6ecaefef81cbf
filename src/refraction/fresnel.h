/// \file
/// Fresnel reflectance of a smooth dielectric: the exact unpolarised equations, and Schlick's
/// approximation beside them.
#pragma once

namespace rb {

/// Which formula gives the share of light a dielectric surface reflects.
enum class FresnelFormula {
    Exact,    ///< The Fresnel equations for unpolarised light.
    Schlick,  ///< Schlick's polynomial: R0 + (1 − R0)(1 − cos θ)^5.
};

/// Everything the Fresnel equations say about one crossing from index eta_i into eta_t.
struct FresnelTerms {
    double Rs = 1.0;          ///< Reflected power, s-polarised (E perpendicular to the plane).
    double Rp = 1.0;          ///< Reflected power, p-polarised (E in the plane of incidence).
    double Ts = 0.0;          ///< Transmitted power, s-polarised.
    double Tp = 0.0;          ///< Transmitted power, p-polarised.
    double cosTheta_t = 0.0;  ///< Cosine of the refraction angle (0 under TIR).
    bool totalInternalReflection = false;  ///< sin θt would exceed 1: nothing is transmitted.

    /// Unpolarised reflectance F = (Rs + Rp) / 2.
    double reflectance() const { return 0.5 * (Rs + Rp); }
    /// Unpolarised transmittance T = (Ts + Tp) / 2 (from the transmitted amplitudes, not 1 − F).
    double transmittance() const { return 0.5 * (Ts + Tp); }
};

/// Cosine of the refraction angle by Snell's law, η_i sin θi = η_t sin θt. Returns false under
/// total internal reflection. cosTheta_i is clamped to [0, 1].
bool snellCosTheta_t(double cosTheta_i, double eta_i, double eta_t, double& cosTheta_t);

/// The Fresnel equations for light arriving at angle θi (cosTheta_i in [0, 1]) from a medium of
/// index eta_i onto one of index eta_t (both > 0): reflected and transmitted power per
/// polarisation.
FresnelTerms fresnelDielectricTerms(double cosTheta_i, double eta_i, double eta_t);

/// Exact unpolarised Fresnel reflectance, fresnelDielectricTerms(...).reflectance() (1 under
/// total internal reflection): what the renderer uses.
double fresnelExact(double cosTheta_i, double eta_i, double eta_t);

/// Schlick's approximation of the unpolarised reflectance. Uses the cosine on the optically
/// thinner side, so it is also right going out of glass (1 beyond the critical angle).
double fresnelSchlick(double cosTheta_i, double eta_i, double eta_t);

/// Reflectance by the chosen formula.
inline double fresnelReflectance(FresnelFormula formula, double cosTheta_i, double eta_i,
                                 double eta_t) {
    return formula == FresnelFormula::Schlick ? fresnelSchlick(cosTheta_i, eta_i, eta_t)
                                              : fresnelExact(cosTheta_i, eta_i, eta_t);
}

}  // namespace rb
