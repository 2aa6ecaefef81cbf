#include "media/media.h"

namespace rb {

Feature mediaFeature() {
    return {"media", 17, "participating media: fog, light shafts and smoke", true, nullptr,
            nullptr};
}

}  // namespace rb
