// A 128-bit digest of a sequence of byte arrays (XXH3): whether the arrays a frame would copy to
// the device are the ones an earlier frame copied, without keeping a second copy to compare.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sheaf {

struct Digest {
    uint64_t low = 0, high = 0;
    bool operator==(const Digest&) const = default;
};

class ContentHasher {
  public:
    ContentHasher();
    ~ContentHasher();
    ContentHasher(const ContentHasher&) = delete;
    ContentHasher& operator=(const ContentHasher&) = delete;

    /// One array: its length, then its bytes, so where one array ends and the next begins
    /// is part of the digest ([ab][c] is not [a][bc]).
    void add(const void* data, size_t bytes);
    template <class T> void add(const std::vector<T>& v) { add(v.data(), v.size() * sizeof(T)); }
    /// A plain value, as an array of one.
    void add_value(uint64_t v) { add(&v, sizeof v); }

    /// The digest of everything added so far.
    Digest digest() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace sheaf
