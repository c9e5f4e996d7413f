// density_file df3 "file": POV-Ray's voxel files. A df3 file is three big-endian 16-bit sizes
// (x, y, z) and then x * y * z values, x fastest, each of 1, 2 or 4 big-endian bytes (the
// file's length says which), read as fractions of the largest value of that size.
#include "io/pov/parser.h"

#include <fstream>
#include <iterator>

namespace sheaf::io::pov {

std::shared_ptr<const PovDensity> Parser::parse_density_file(const Token& keyword) {
    accept_kw("df3");
    const Token& name = peek();
    const std::string file = parse_string();
    const std::string path = find_file(file, name, "density file", {".df3"});
    // Read once per file: the patterns that name it share its voxels.
    if (auto it = densities_.find(path); it != densities_.end()) return it->second;
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    auto bad = [&](const std::string& why) {
        error_at(name, "density file '" + path + "' " + why +
                           " (expected a df3 file: three "
                           "big-endian 16-bit sizes, then the voxels)");
    };
    if (!in.eof() && in.fail()) bad("cannot be read");
    if (bytes.size() < 6) bad("is shorter than its 6-byte header");
    auto size = [&](size_t at) { return uint32_t(bytes[at]) << 8 | bytes[at + 1]; };
    auto d = std::make_shared<PovDensity>();
    d->nx = size(0), d->ny = size(2), d->nz = size(4);
    const uint64_t n = uint64_t(d->nx) * d->ny * d->nz;
    if (n == 0) bad("has a size of 0");
    const uint64_t data = bytes.size() - 6;
    if (data % n != 0 || (data / n != 1 && data / n != 2 && data / n != 4))
        bad("holds " + std::to_string(data) + " bytes of voxels, not 1, 2 or 4 for each of its " +
            std::to_string(d->nx) + " x " + std::to_string(d->ny) + " x " + std::to_string(d->nz));
    const size_t width = size_t(data / n);
    const double largest = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
    auto values = std::make_shared<std::vector<float>>(size_t(n));
    for (size_t i = 0; i < values->size(); ++i) {
        uint64_t v = 0;
        for (size_t b = 0; b < width; ++b) v = v << 8 | bytes[6 + i * width + b];
        (*values)[i] = float(double(v) / largest);
    }
    d->values = std::move(values);
    densities_.emplace(path, d);
    return d;
}

} // namespace sheaf::io::pov
