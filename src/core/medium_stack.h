/// \file
/// MediumStack: the closed objects a path is inside, each with its index of refraction.
#pragma once

namespace rb {

struct Instance;

/// The objects a ray is inside, innermost last (seed 001's IOR stack). The core only carries
/// it along a path; chapter 5 (refraction) pushes on entering a refracting object and pops on
/// leaving, so nested media such as water inside glass bend light correctly.
struct MediumStack {
    /// The most objects the stack holds. Deeper nesting keeps the innermost kMaxDepth and
    /// forgets the outermost ones: the media around the ray now, which the surfaces it meets
    /// next separate, stay exact, and every surface on the way in is crossed right. The cost
    /// comes on the way out, after kMaxDepth − 1 exits: leaving the outermost object kept
    /// leads into air instead of the forgotten medium around it, and each forgotten object is
    /// then left from its own index into air (crossSurface's "started inside" case), which is
    /// right only for the outermost. Keeping the outermost entries instead would give the
    /// wrong index inside every object deeper than kMaxDepth, where the ray is.
    static constexpr int kMaxDepth = 16;
    struct Entry {
        const Instance* instance;  ///< The object the ray is inside.
        double ior;                ///< Its index of refraction.
    };
    Entry entries[kMaxDepth];
    int size = 0;

    /// Index of refraction of the medium the ray travels in (1 = vacuum/air).
    double currentIor() const { return size > 0 ? entries[size - 1].ior : 1.0; }
    /// True when the ray is inside `instance`.
    bool contains(const Instance* instance) const {
        for (int i = 0; i < size; ++i)
            if (entries[i].instance == instance) return true;
        return false;
    }
    /// This stack with `instance` entered; when full, the outermost entry is dropped first.
    MediumStack entered(const Instance* instance, double ior) const {
        MediumStack s = *this;
        if (s.size == kMaxDepth) {
            for (int i = 1; i < kMaxDepth; ++i) s.entries[i - 1] = s.entries[i];
            --s.size;
        }
        s.entries[s.size++] = {instance, ior};
        return s;
    }
    /// This stack with `instance` left (wherever it is in the stack).
    MediumStack left(const Instance* instance) const {
        MediumStack s;
        for (int i = 0; i < size; ++i)
            if (entries[i].instance != instance) s.entries[s.size++] = entries[i];
        return s;
    }
    /// The index of refraction beyond the surface of `instance`: where the ray goes if it
    /// crosses that surface now.
    double iorBeyond(const Instance* instance, double iorOfInstance) const {
        return contains(instance) ? left(instance).currentIor() : iorOfInstance;
    }
};

}  // namespace rb
