/// \file
/// Crossings: every place a line passes through a closed surface, in order. What a CSG
/// operand must report, because combining solids needs their intervals, not just a first hit.
#pragma once

#include <cstddef>
#include <new>
#include <type_traits>
#include <vector>

#include "core/hit.h"

namespace rb {

/// One pass of the line o + t·d through a closed surface.
struct Crossing {
    ObjectHit hit;  ///< t, the normal (pointing out of the solid) and the part's material.
    bool entering;  ///< True where the line goes from outside the solid to inside.
};

/// The crossings of one line with one solid, in increasing t. Consecutive pairs
/// (entering, leaving) are the solid's intervals along the line. Holds a few crossings
/// inline and spills to the heap beyond that, so the usual case allocates nothing.
class CrossingList {
  public:
    CrossingList() = default;
    CrossingList(const CrossingList& other) { *this = other; }
    /// A copy of every crossing of `other`.
    CrossingList& operator=(const CrossingList& other) {
        clear();
        for (size_t i = 0; i < other.size(); ++i) push(other[i]);
        return *this;
    }
    /// The number of crossings.
    size_t size() const { return size_; }
    /// True when the line misses the solid.
    bool empty() const { return size_ == 0; }
    /// Crossing i (in increasing t).
    const Crossing& operator[](size_t i) const {
        return i < kInline ? inlineAt(i) : spill_[i - kInline];
    }
    /// Crossing i, writable.
    Crossing& operator[](size_t i) { return i < kInline ? inlineAt(i) : spill_[i - kInline]; }
    /// Append a crossing (the caller keeps t increasing).
    void push(const Crossing& c) {
        if (size_ < kInline)
            new (&storage_[size_ * sizeof(Crossing)]) Crossing(c);
        else
            spill_.push_back(c);
        ++size_;
    }
    /// Remove the last crossing.
    void pop() {
        if (size_ > kInline) spill_.pop_back();
        --size_;
    }
    /// Remove every crossing.
    void clear() {
        size_ = 0;
        spill_.clear();
    }

  private:
    static constexpr size_t kInline = 8;
    // Crossings are trivially copyable; the inline ones live in raw storage so that a new list
    // (one per operand per ray) costs nothing until something is pushed.
    static_assert(std::is_trivially_copyable_v<Crossing> &&
                  std::is_trivially_destructible_v<Crossing>);
    Crossing& inlineAt(size_t i) {
        return *std::launder(reinterpret_cast<Crossing*>(&storage_[i * sizeof(Crossing)]));
    }
    const Crossing& inlineAt(size_t i) const {
        return *std::launder(reinterpret_cast<const Crossing*>(&storage_[i * sizeof(Crossing)]));
    }
    alignas(Crossing) unsigned char storage_[kInline * sizeof(Crossing)];
    std::vector<Crossing> spill_;
    size_t size_ = 0;
};

}  // namespace rb
