#include "bvh/triangle.h"

namespace rb {

// [watertight-ray]
WatertightRay::WatertightRay(const Ray& r) : o(r.o) {
    // Choose z as the axis where |d| is largest, and keep the winding by swapping x and y
    // when d_z is negative.
    const Vec3 a = glm::abs(r.d);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (r.d[kz] < 0.0) std::swap(kx, ky);
    // The shear that maps d to (0, 0, 1).
    Sx = r.d[kx] / r.d[kz];
    Sy = r.d[ky] / r.d[kz];
    Sz = 1.0 / r.d[kz];
}
// [watertight-ray]

}  // namespace rb
