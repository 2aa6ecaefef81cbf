// Chapter 15 plugs in as a shape kind: its Lua calls make nodes holding a Cylinder or Cone,
// and the core intersects them like any shape. Nothing is installed into the pipeline, so a
// scene without quadrics runs exactly the code it ran before. Switched off, the core leaves
// the quadrics' instances out of the scene (Shape::feature), as if the chapter were not written.
#include "quadrics/quadrics.h"

namespace rb {

Feature quadricsFeature() {
    return {"quadrics", 15,           "cylinders and cones: capped, open and frustum",
            true,       bindQuadrics, nullptr};
}

}  // namespace rb
