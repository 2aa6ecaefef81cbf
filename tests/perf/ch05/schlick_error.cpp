// ch05_schlick_error: Schlick's approximation against the exact unpolarised Fresnel
// reflectance, over the angle of incidence, for water (1.33), glass (1.5) and diamond (2.4),
// going in (from air) and going out (into air).
//
// usage: ch05_schlick_error OUT_DIR
//   OUT_DIR/schlick-error.dat   angle (degrees), then Schlick − exact for
//                               in 1.33, in 1.5, in 2.4, out 1.33, out 1.5, out 2.4 (raybook's
//                               Schlick, which takes the angle outside when going out), and
//                               out 1.33, out 1.5, out 2.4 with the naive cos θi
//   OUT_DIR/finding.txt         the largest errors, in one sentence
#include <cmath>
#include <cstdio>
#include <string>

#include "refraction/fresnel.h"

namespace {

/// Schlick's polynomial evaluated at the angle of incidence whichever way the light goes:
/// the common mistake raybook's fresnelSchlick avoids when going out of a dense medium.
double schlickNaive(double cosTheta_i, double eta_i, double eta_t) {
    const double r = (eta_i - eta_t) / (eta_i + eta_t);
    const double R0 = r * r;
    const double m = 1.0 - cosTheta_i;
    return R0 + (1.0 - R0) * m * m * m * m * m;
}

struct Worst {
    double error = 0.0;  ///< Signed error of largest magnitude.
    double angle = 0.0;  ///< Where, in degrees.
    void see(double e, double a) {
        if (std::abs(e) > std::abs(error)) error = e, angle = a;
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ch05_schlick_error OUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    std::FILE* out = std::fopen((dir + "/schlick-error.dat").c_str(), "w");
    if (!out) return 1;
    const double etas[3] = {1.33, 1.5, 2.4};
    Worst in[3], outward[3], naive[3];
    std::fprintf(
        out, "# angle  in1.33 in1.5 in2.4  out1.33 out1.5 out2.4  naive1.33 naive1.5 naive2.4\n");
    const int steps = 9000;  // 0.01° apart
    for (int k = 0; k <= steps; ++k) {
        const double degrees = 90.0 * k / steps;
        const double c = std::cos(degrees * M_PI / 180.0);
        std::fprintf(out, "%.2f", degrees);
        double e[9];
        for (int j = 0; j < 3; ++j) {
            const double n = etas[j];
            e[j] = rb::fresnelSchlick(c, 1.0, n) - rb::fresnelExact(c, 1.0, n);
            e[3 + j] = rb::fresnelSchlick(c, n, 1.0) - rb::fresnelExact(c, n, 1.0);
            e[6 + j] = schlickNaive(c, n, 1.0) - rb::fresnelExact(c, n, 1.0);
            in[j].see(e[j], degrees);
            outward[j].see(e[3 + j], degrees);
            naive[j].see(e[6 + j], degrees);
        }
        for (double v : e) std::fprintf(out, " %.9f", v);
        std::fprintf(out, "\n");
    }
    std::fclose(out);

    std::FILE* finding = std::fopen((dir + "/finding.txt").c_str(), "w");
    if (!finding) return 1;
    std::fprintf(finding,
                 "Going in, Schlick is off by at most %+.4f (n = 1.33, at %.1f deg), %+.4f "
                 "(n = 1.5, at %.1f deg) and %+.4f (n = 2.4, at %.1f deg), always near grazing; "
                 "going out it has the same worst errors (%+.4f, %+.4f, %+.4f) when evaluated at "
                 "the outside angle, but evaluated at the inside angle it misses total internal "
                 "reflection and is off by up to %+.3f, %+.3f and %+.3f.\n",
                 in[0].error, in[0].angle, in[1].error, in[1].angle, in[2].error, in[2].angle,
                 outward[0].error, outward[1].error, outward[2].error, naive[0].error,
                 naive[1].error, naive[2].error);
    std::fclose(finding);
    return 0;
}
