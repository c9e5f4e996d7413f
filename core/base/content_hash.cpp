#include "core/base/content_hash.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

namespace sheaf {

namespace {
constexpr size_t kPiece = size_t(1) << 22;        // 4 MiB
constexpr size_t kParallelFrom = size_t(1) << 24; // 16 MiB
} // namespace

struct ContentHasher::State {
    XXH3_state_t xxh;
};

ContentHasher::ContentHasher() : state_(std::make_unique<State>()) {
    XXH3_128bits_reset(&state_->xxh);
}

ContentHasher::~ContentHasher() = default;

void ContentHasher::add(const void* data, size_t bytes) {
    const uint64_t length = bytes;
    XXH3_128bits_update(&state_->xxh, &length, sizeof length);
    if (bytes <= kParallelFrom) {
        if (bytes > 0) XXH3_128bits_update(&state_->xxh, data, bytes);
        return;
    }
    // A large array (a mesh's triangles): its pieces' digests on every core, then those, in
    // order, into the whole's. Deterministic: the pieces are fixed.
    const size_t pieces = (bytes + kPiece - 1) / kPiece;
    std::vector<XXH128_hash_t> digests(pieces);
    const auto* bytes_at = static_cast<const unsigned char*>(data);
    tbb::parallel_for(size_t(0), pieces, [&](size_t i) {
        const size_t begin = i * kPiece;
        digests[i] = XXH3_128bits(bytes_at + begin, std::min(kPiece, bytes - begin));
    });
    XXH3_128bits_update(&state_->xxh, digests.data(), digests.size() * sizeof(XXH128_hash_t));
}

Digest ContentHasher::digest() const {
    const XXH128_hash_t h = XXH3_128bits_digest(&state_->xxh);
    return Digest{h.low64, h.high64};
}

} // namespace sheaf
