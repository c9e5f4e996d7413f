// Image textures for the core through OpenImageIO's TextureSystem (cached, filtered,
// mip-mapped), in the image module (io/image/image_module_abi.h): the TextureSampler the
// renderer asks for colours.
#pragma once

#include "core/scene/prepared_scene.h"

namespace sheaf::io {

/// Opens every texture of the scene and attaches a sampler to it. A missing or unreadable
/// texture is a SceneError naming the file and where the scene asked for it. Scenes without
/// textures are left as they are.
void attach_texture_sampler(PreparedScene& scene);

/// What scene readers are given to sample the images of pigments they evaluate themselves
/// (POV-Ray's pigment functions in the scene language): attach_texture_sampler, or nullptr in
/// programs that read no images (as RasterReader, io/image/raster.h).
using SamplerAttacher = void (*)(PreparedScene& scene);

} // namespace sheaf::io
