/* The Sheaf C ABI: build a scene, choose settings, render a frame and read back its passes,
 * statistics and images. C99; usable from C and C++. Every function returns a SheafError unless
 * documented otherwise; sheafGetLastError() explains the last failure on the calling thread.
 * See docs/capi.md. */
#ifndef SHEAF_SHEAF_H
#define SHEAF_SHEAF_H

#include <stddef.h>
#include <stdint.h>

#include "sheaf/sheaf_version.h" /* SHEAF_VERSION_MAJOR, _MINOR, _PATCH, _STRING */

#if defined(_WIN32)
#if defined(SHEAF_BUILDING_LIBRARY)
#define SHEAF_API __declspec(dllexport)
#else
#define SHEAF_API __declspec(dllimport)
#endif
#else
#define SHEAF_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Handles: reference counted (atomically); New returns one reference. ---- */

typedef struct SheafSceneT* SheafScene;
typedef struct SheafRendererT* SheafRenderer;
typedef struct SheafFrameT* SheafFrame;

/* ---- Errors ---- */

typedef enum SheafError {
    SHEAF_OK = 0,
    SHEAF_ERROR_INVALID_ARGUMENT = 1, /* a NULL handle or pointer, an index out of range */
    SHEAF_ERROR_INVALID_SETTING = 2,  /* an unknown setting key or a value out of range */
    SHEAF_ERROR_SCENE = 3,            /* a scene that cannot be loaded or rendered */
    SHEAF_ERROR_RENDER = 4,           /* a failure while rendering */
    SHEAF_ERROR_IO = 5,               /* an image that cannot be written */
    SHEAF_ERROR_OUT_OF_MEMORY = 6,    /* a frame larger than the memory available */
    SHEAF_ERROR_CANCELLED = 7, /* the progress callback returned 0 */
    SHEAF_ERROR_UNKNOWN = 99
} SheafError;

/* The outcome of the calling thread's most recent call that returns a SheafError (SHEAF_OK and ""
 * after a success). *message (when message is not NULL) stays valid until the thread's next sheaf
 * call. Needs no handle. */
SHEAF_API SheafError sheafGetLastError(const char** message);

/* Called on every error, from the thread that made the failing call. Global; NULL removes it. */
typedef void (*SheafErrorCallback)(void* user, SheafError code, const char* message);
SHEAF_API void sheafSetErrorCallback(SheafErrorCallback callback, void* user);

/* ---- Version ---- */

/* Any of the pointers may be NULL. */
SHEAF_API void sheafGetVersion(int* major, int* minor, int* patch);
/* "MAJOR.MINOR.PATCH"; static storage. */
SHEAF_API const char* sheafGetVersionString(void);

/* ---- Built-in scenes (strings have static storage) ---- */

/* The scene `render` draws when given none, e.g. "cornell". */
SHEAF_API const char* sheafGetDefaultSceneName(void);
SHEAF_API SheafError sheafGetBuiltinSceneCount(size_t* count);
SHEAF_API SheafError sheafGetBuiltinSceneName(size_t index, const char** name);

/* ---- Scenes ---- */

typedef struct SheafMaterialDesc {
    float color[3]; /* linear RGB */
    float ambient, diffuse, specular, phong_exponent;
    float mirror;       /* mirror reflection weight */
    float transmission; /* refracted share, split with reflection by Fresnel */
    float ior;
    float emission[3]; /* radiance the surface gives off by itself, linear RGB */
    int32_t texture;   /* an id from sheafSceneAddTexture multiplying `color`, or -1 */
} SheafMaterialDesc;

/* Fills *desc with the engine's default material. */
SHEAF_API void sheafMaterialDescInit(SheafMaterialDesc* desc);

/* An empty scene (no geometry, the default camera, a black background). */
SHEAF_API SheafError sheafSceneNew(SheafScene* out);
SHEAF_API SheafError sheafSceneRetain(SheafScene scene);
SHEAF_API SheafError sheafSceneRelease(SheafScene scene);

/* Replaces the content with a built-in scene ("cornell", ...). */
SHEAF_API SheafError sheafSceneLoadBuiltin(SheafScene scene, const char* name);
/* Replaces the content with a scene file (.pov, .inc: POV-Ray 3.7's scene language; .xml: Sheaf's
 * XML scenes; .obj .ply .gltf .glb: a mesh with a default camera and light), or a
 * built-in scene for "builtin:NAME". Errors name the file, line and column. What the file asks
 * for and the engine cannot show is kept as warnings (sheafSceneGetWarning). */
SHEAF_API SheafError sheafSceneLoadFile(SheafScene scene, const char* path);
/* Options for what builds the scene, by name. For sheafSceneLoadFile:
 *   "include_path"  a folder searched for #include after the scene's own (appends; "" clears)
 *   "strict"        "1": an unsupported feature is an error (SHEAF_ERROR_SCENE); "0": a warning
 *   "image_width", "image_height"  the size the scene will be rendered at, for scenes that ask
 *                   (POV-Ray's image_width and image_height); 512 when not set
 *   "initial_frame", "final_frame"  POV-Ray's animation (integers, both 1 when not set): a
 *                   sequence when they differ; "frame" the frame to read (initial_frame when
 *                   not set); "initial_clock", "final_clock" (0 and 1) the clock at the first and
 *                   last frame, in between linearly; "cyclic_animation" "1": the last frame
 *                   stops one step short of final_clock. The scene sees POV-Ray 3.7's clock,
 *                   frame_number, initial_frame, final_frame, initial_clock, final_clock,
 *                   clock_delta and clock_on. A final_frame below initial_frame, or a frame
 *                   outside them, fails sheafSceneLoadFile with SHEAF_ERROR_INVALID_ARGUMENT
 *   "clock"         a still's clock (POV-Ray's +K; clock_on is then 1); "" unsets it
 *   "declare"       "NAME=NUMBER": a float declared before the scene's first line (POV-Ray's
 *                   Declare=); appends, "" clears
 *   "limit.parse_steps", "limit.objects", "limit.data_mib", "limit.loop_iterations",
 *   "limit.macro_calls", "limit.function_terms"  the POV-Ray reader's budgets (an integer in
 *                   1..2^50; "" the default): tokens read and function terms evaluated, objects
 *                   parsed, MiB of arrays, strings and objects held, runs of all loops, macro
 *                   calls, function terms evaluated while the file is read. A scene past one
 *                   fails with SHEAF_ERROR_SCENE at the place it did; docs/pov.md, "Limits",
 *                   gives the defaults
 * For sheafSceneAddSubdivisionMesh:
 *   "subdivision.limit"     "1": every refined vertex moves onto the limit surface; "0" (default)
 *   "subdivision.boundary"  "edge_only" (default), "edge_and_corner" or "none" */
SHEAF_API SheafError sheafSceneSetLoadOption(SheafScene scene, const char* key, const char* value);
/* The warnings of the last sheafSceneLoadFile ("FILE:LINE:COL: warning: unsupported ..."), in
 * order; *message stays valid until the scene is loaded again or released. */
SHEAF_API SheafError sheafSceneGetWarningCount(SheafScene scene, size_t* count);
SHEAF_API SheafError sheafSceneGetWarning(SheafScene scene, size_t index, const char** message);
/* What the last sheafSceneLoadFile used of the reader's limits (the load options limit.*), in
 * order: the limit's name ("parse_steps", "objects", "data_mib", "loop_iterations",
 * "macro_calls", "function_terms"), the amount used (the data's peak, the others' totals) and the
 * limit. None for formats without such limits
 * or a built-in scene; *name stays valid until the scene is loaded again or released. */
SHEAF_API SheafError sheafSceneGetLimitCount(SheafScene scene, size_t* count);
SHEAF_API SheafError sheafSceneGetLimitUse(SheafScene scene, size_t index, const char** name,
                                           double* used, double* limit);

/* Ids count from 0 in the order of addition; out ids may be NULL. */
SHEAF_API SheafError sheafSceneAddMaterial(SheafScene scene, const SheafMaterialDesc* desc,
                                           uint32_t* out_material_id);
/* positions: 3 floats per vertex; indices: 3 per triangle; normals: 3 floats per vertex, or NULL
 * for flat shading. The data is copied. */
SHEAF_API SheafError sheafSceneAddMesh(SheafScene scene, const float* positions,
                                       uint32_t vertex_count, const uint32_t* indices,
                                       uint32_t triangle_count, const float* normals,
                                       uint32_t* out_mesh_id);
/* Places a mesh with a material; many objects may share one mesh (instancing).
 * transform_3x4: row-major [R | t], NULL for the identity. name may be NULL. */
SHEAF_API SheafError sheafSceneAddObject(SheafScene scene, uint32_t mesh_id, uint32_t material_id,
                                         const float* transform_3x4, const char* name,
                                         uint32_t* out_object_id);

/* What an object takes part in (bits; 0 for everything). */
enum {
    SHEAF_OBJECT_NO_SHADOW = 1,     /* casts no shadow (shadow and AO rays pass it) */
    SHEAF_OBJECT_NO_REFLECTION = 2, /* not seen in reflections */
    SHEAF_OBJECT_NO_IMAGE = 4       /* not seen by the camera (still shadows and reflects) */
};
/* Sets the flags of an object from sheafSceneAddObject. */
SHEAF_API SheafError sheafSceneSetObjectFlags(SheafScene scene, uint32_t object_id, uint32_t flags);
SHEAF_API SheafError sheafSceneAddPointLight(SheafScene scene, const float position[3],
                                             const float color[3]);
SHEAF_API SheafError sheafSceneSetCamera(SheafScene scene, const float position[3],
                                         const float look_at[3], const float up[3],
                                         float fov_y_degrees);
SHEAF_API SheafError sheafSceneSetBackground(SheafScene scene, const float rgb[3]);

typedef enum SheafTextureMapping {
    SHEAF_MAPPING_UV = 0,          /* the mesh's texture coordinates (sheafSceneSetMeshUvs) */
    SHEAF_MAPPING_PLANAR = 1,      /* (x, y) in texture space, repeating every unit */
    SHEAF_MAPPING_SPHERICAL = 2,   /* longitude and latitude around the texture-space origin */
    SHEAF_MAPPING_CYLINDRICAL = 3, /* angle around texture-space y, and y */
    SHEAF_MAPPING_TORUS = 4        /* angle around y, and around the xz plane's unit circle */
} SheafTextureMapping;

/* An image texture read through OpenImageIO (png, jpeg, tga, tiff, exr, hdr, ...).
 * world_to_texture_3x4: row-major, NULL for the identity (used by the projections).
 * colorspace: NULL or "" to follow the file (8-bit sRGB, float linear), "srgb" or "linear".
 * The file is opened when the scene is committed: a missing one is SHEAF_ERROR_SCENE. */
SHEAF_API SheafError sheafSceneAddTexture(SheafScene scene, const char* path,
                                          int mapping /* a SheafTextureMapping */,
                                          const float* world_to_texture_3x4, const char* colorspace,
                                          uint32_t* out_texture_id);
/* Texture coordinates of a mesh: 2 floats per vertex (t = 0 at the bottom of the image). */
SHEAF_API SheafError sheafSceneSetMeshUvs(SheafScene scene, uint32_t mesh_id, const float* uvs,
                                          uint32_t vertex_count);

typedef enum SheafLightType {
    SHEAF_LIGHT_POINT = 0,
    SHEAF_LIGHT_SPOT = 1,
    SHEAF_LIGHT_PARALLEL = 2 /* a sun: every ray parallel to `direction` */
} SheafLightType;

typedef struct SheafLightDesc {
    int type;             /* a SheafLightType; any other value is SHEAF_ERROR_INVALID_ARGUMENT */
    float position[3];    /* point and spot */
    float direction[3];   /* spot: the cone's axis; parallel: the way the light travels */
    float color[3];       /* linear RGB intensity */
    float spot_radius;    /* spot: degrees from the axis at full intensity (>= 90: no cone) */
    float spot_falloff;   /* spot: degrees from the axis where the light reaches zero */
    float spot_tightness; /* spot: intensity times cos(angle)^tightness; 0 for none */
    float fade_distance;  /* > 0: intensity times 2 / (1 + (d / fade_distance)^fade_power) */
    float fade_power;
    int shadowless; /* non-zero: no shadow rays */
} SheafLightDesc;

/* Fills *desc with a white point light at the origin (the engine's defaults). */
SHEAF_API void sheafLightDescInit(SheafLightDesc* desc);
SHEAF_API SheafError sheafSceneAddLight(SheafScene scene, const SheafLightDesc* desc,
                                        uint32_t* out_light_id);

/* Perspective and orthographic views are rasterised; the others are POV-Ray's camera types,
 * whose primary rays are traced, shaped by sheafSceneSetCameraLens (docs/capi.md). */
typedef enum SheafProjection {
    SHEAF_PROJECTION_PERSPECTIVE = 0,
    SHEAF_PROJECTION_ORTHOGRAPHIC = 1,
    SHEAF_PROJECTION_FISHEYE = 2,
    SHEAF_PROJECTION_ULTRA_WIDE_ANGLE = 3,
    SHEAF_PROJECTION_OMNIMAX = 4,
    SHEAF_PROJECTION_PANORAMIC = 5,
    SHEAF_PROJECTION_CYLINDER_1 = 6,
    SHEAF_PROJECTION_CYLINDER_2 = 7,
    SHEAF_PROJECTION_CYLINDER_3 = 8,
    SHEAF_PROJECTION_CYLINDER_4 = 9,
    SHEAF_PROJECTION_SPHERICAL = 10
} SheafProjection;

typedef struct SheafCameraDesc {
    int projection; /* a SheafProjection; any other value is SHEAF_ERROR_INVALID_ARGUMENT */
    float position[3], look_at[3], up[3];
    float fov_y_degrees; /* perspective: vertical field of view */
    float ortho_height;  /* orthographic: height of the view in scene units */
    float shift[2];      /* lens shift in image widths and heights (off-axis views) */
} SheafCameraDesc;

/* Fills *desc with the engine's default camera. */
SHEAF_API void sheafCameraDescInit(SheafCameraDesc* desc);
SHEAF_API SheafError sheafSceneSetCameraDesc(SheafScene scene, const SheafCameraDesc* desc);
/* The traced projections' shape, for the camera last set (perspective and orthographic ignore
 * it): the angle in degrees (90 by default, spherical 360) and spherical's vertical angle (180),
 * each in (0, 3600]; `lengths`: POV-Ray's lengths of right, up and direction (1 1 1 by default;
 * NULL keeps them). sheafSceneSetCameraDesc resets them to the defaults. */
SHEAF_API SheafError sheafSceneSetCameraLens(SheafScene scene, float angle_degrees,
                                             float v_angle_degrees, const float lengths[3]);
/* Depth of field for the camera last set (perspective and orthographic; checked at commit): each
 * anti-aliasing sample of a pixel ("aa.samples") leaves from its own point of a lens of radius
 * `lens_radius` (scene units, >= 0; 0: none) across the view, aimed through the point its pixel
 * sees on the plane `focal_distance` (> 0 with a lens) ahead, which stays sharp.
 * sheafSceneSetCameraDesc resets it to none. */
SHEAF_API SheafError sheafSceneSetCameraFocus(SheafScene scene, float lens_radius,
                                              float focal_distance);
/* Validates the scene and prepares it for rendering. sheafRender commits a scene that was never
 * committed or was changed since. */
SHEAF_API SheafError sheafSceneCommit(SheafScene scene);

/* ---- Renderers and settings (keys and values as in docs/settings.md) ---- */

SHEAF_API SheafError sheafRendererNew(SheafRenderer* out);
SHEAF_API SheafError sheafRendererRetain(SheafRenderer renderer);
SHEAF_API SheafError sheafRendererRelease(SheafRenderer renderer);

SHEAF_API SheafError sheafRendererSetString(SheafRenderer renderer, const char* key,
                                            const char* value);
SHEAF_API SheafError sheafRendererSetInt(SheafRenderer renderer, const char* key, long long value);
SHEAF_API SheafError sheafRendererSetFloat(SheafRenderer renderer, const char* key, double value);
SHEAF_API SheafError sheafRendererSetBool(SheafRenderer renderer, const char* key, int value);
/* Back to the scene's value or the default. */
SHEAF_API SheafError sheafRendererUnset(SheafRenderer renderer, const char* key);
/* The explicit value, else the default, in canonical text. snprintf-style: writes at most `size`
 * bytes including the NUL; *needed (when not NULL) = length + 1; buf may be NULL when size is 0. */
SHEAF_API SheafError sheafRendererGetString(SheafRenderer renderer, const char* key, char* buf,
                                            size_t size, size_t* needed);
/* The value a render of `scene` with `renderer` uses: the renderer's explicit value, else the
 * scene's own (what its file set), else the default. Commits the scene when needed.
 * snprintf-style, as sheafRendererGetString. */
SHEAF_API SheafError sheafRendererGetEffective(SheafRenderer renderer, SheafScene scene,
                                               const char* key, char* buf, size_t size,
                                               size_t* needed);
/* Applies every value of a preset: a name (NAME.xml in $SHEAF_PRESET_PATH, ':'-separated, then
 * <libdir>/../share/sheaf/presets) or a path (containing '/' or ending in .xml). */
SHEAF_API SheafError sheafRendererLoadPreset(SheafRenderer renderer, const char* name_or_path);
/* The presets sheafRendererLoadPreset finds by name, one line each: "NAME\tDESCRIPTION\n",
 * sorted by name. snprintf-style, as sheafRendererGetString. Needs no handle. */
SHEAF_API SheafError sheafGetPresetList(char* buf, size_t size, size_t* needed);
/* Called between stages with the share done (0..1); return 0 to cancel the render, which then
 * fails with SHEAF_ERROR_CANCELLED. NULL removes it. */
typedef int (*SheafProgressCallback)(void* user, float done);
SHEAF_API SheafError sheafRendererSetProgressCallback(SheafRenderer renderer,
                                                      SheafProgressCallback callback, void* user);

/* Every known setting. The strings have static storage; any out pointer may be NULL. */
SHEAF_API SheafError sheafGetSettingCount(size_t* count);
SHEAF_API SheafError sheafGetSettingInfo(size_t index, const char** key, const char** default_value,
                                         const char** allowed, const char** help);

/* ---- Rendering and frames ---- */

/* Renders one frame with the renderer's settings over the scene's own. *out receives a new
 * reference. */
SHEAF_API SheafError sheafRender(SheafRenderer renderer, SheafScene scene, SheafFrame* out);
SHEAF_API SheafError sheafFrameRetain(SheafFrame frame);
SHEAF_API SheafError sheafFrameRelease(SheafFrame frame);

SHEAF_API SheafError sheafFrameGetSize(SheafFrame frame, int* width, int* height);
/* Where the frame's image lies in the whole frame: its first column *x and row *y, and the
 * whole frame's size. A frame rendered with the region.* settings holds only that part (its
 * size is sheafFrameGetSize's); otherwise 0, 0 and the frame's own size. Every pixel of a part
 * equals the same pixel of the whole frame, so parts put together give it exactly. */
SHEAF_API SheafError sheafFrameGetRegion(SheafFrame frame, int* x, int* y, int* full_width,
                                         int* full_height);
/* Reads back a frame saved by sheafFrameSaveImage as OpenEXR with output.exr=float: its
 * passes, its place in the whole frame (the file's data window), settings and statistics.
 * *out receives a new reference. Fails naming the file when it is not such a frame (a half
 * float EXR does not hold the frame's values). */
SHEAF_API SheafError sheafFrameLoadImage(const char* path, SheafFrame* out);
/* Puts the parts of one frame (rendered with region.* settings, in any order) together into
 * the whole frame: every pass they keep, their settings without region.*, their statistics
 * summed (frame.* and scene.* the whole frame's, memory.* the largest part's; frame.parts
 * counts them). The result equals the frame rendered in one piece. Fails naming the part when
 * parts are of different frames or settings, overlap, or leave pixels uncovered. *out
 * receives a new reference. */
SHEAF_API SheafError sheafFrameAssemble(const SheafFrame* parts, size_t count, SheafFrame* out);
/* Copies a pass, top row first: "combined" (4 floats per pixel, scene-linear RGBA), "depth" (1,
 * +inf where nothing was hit), "normal" (3), "albedo" (3), "object_id" (1, -1 where nothing was
 * hit), "tests" (1, the exact ray-primitive tests of the pixel's secondary rays: where the
 * hierarchy works hardest). float_count is the capacity of dst in floats. A frame keeps the
 * passes the setting output.passes names (all by default); asking for another is
 * SHEAF_ERROR_INVALID_ARGUMENT, its message naming the setting. */
SHEAF_API SheafError sheafFrameGetPass(SheafFrame frame, const char* pass, float* dst,
                                       size_t float_count);
/* Statistics (docs/statistics.md). *key stays valid as long as the frame. */
SHEAF_API SheafError sheafFrameGetStatCount(SheafFrame frame, size_t* count);
SHEAF_API SheafError sheafFrameGetStat(SheafFrame frame, size_t index, const char** key,
                                       double* value);
SHEAF_API SheafError sheafFrameGetStatByName(SheafFrame frame, const char* key, double* value);
/* what: "stats.json", "stats.table", "settings" (one "key=value" line per effective setting)
 * or "backend" (where the frame was computed and why, in one line: "backend: cpu (no CUDA
 * device: ...)"). snprintf-style, as sheafRendererGetString. */
SHEAF_API SheafError sheafFrameGetText(SheafFrame frame, const char* what, char* buf, size_t size,
                                       size_t* needed);
/* Writes the frame; the format follows the extension. 8-bit files (.png .jpg .tif) are
 * display-referred through OpenColorIO (settings output.display, output.view, output.look,
 * output.ocio_config); .exr is scene-linear with every pass kept as named channels (R G B A, Z,
 * N.X N.Y N.Z, albedo.R/G/B, object_id, tests; output.exr = half or float colour); .hdr is
 * scene-linear RGB. Settings and statistics go into the file's metadata. */
SHEAF_API SheafError sheafFrameSaveImage(SheafFrame frame, const char* path);
/* Writes one pass as an 8-bit false-colour picture (.png .jpg .tif): "combined", "depth" (grey,
 * near is bright), "normal" (0.5 + 0.5 n), "albedo", "object_id" (a colour per object),
 * "tests" (a heat map of the intersection tests per pixel, log scale). */
SHEAF_API SheafError sheafFrameSavePass(SheafFrame frame, const char* pass, const char* path);

/* ---- Images ---- */

/* Writes any image: width x height pixels of `channels` floats each (1 gray, 2 gray+alpha, 3 RGB,
 * 4 RGBA), top row first. The format follows the extension: .png .tif .tiff (8-bit, alpha kept),
 * .jpg .jpeg (8-bit, alpha dropped), .exr (half float), .hdr (float RGB; gray is repeated).
 * display_referred non-zero: the values are scene-linear and 8-bit files get the display
 * transform of the OpenColorIO config's default display ($OCIO, else the shipped config: sRGB)
 * on the colour channels (not alpha); 0: they are written as given. 8-bit files clamp to [0, 1];
 * .exr and .hdr are always written as given. Needs no handle. */
SHEAF_API SheafError sheafWriteImage(const char* path, int width, int height, int channels,
                                     const float* pixels, int display_referred);

/* ---- Subdivision surfaces (OpenSubdiv) ---- */

typedef enum SheafSubdivScheme { SHEAF_SUBDIV_CATMULL_CLARK = 0, SHEAF_SUBDIV_LOOP = 1 } SheafSubdivScheme;
/* A polygon cage refined uniformly by OpenSubdiv to `level` (0..8) and added as a triangle mesh with smooth normals.
 * positions: 3 floats per vertex; face_sizes: vertices per face; face_indices: the faces' vertex indices, concatenated.
 * crease_edges: 2 vertex indices per crease (NULL when crease_count is 0); crease_sharpness: one per crease.
 * uvs: 2 floats per vertex or NULL. */
SHEAF_API SheafError sheafSceneAddSubdivisionMesh(SheafScene scene, const float* positions, uint32_t vertex_count,
    const uint32_t* face_sizes, uint32_t face_count, const uint32_t* face_indices,
    const uint32_t* crease_edges, const float* crease_sharpness, uint32_t crease_count,
    const float* uvs, int scheme /* a SheafSubdivScheme */, int level, uint32_t* out_mesh_id);

#ifdef __cplusplus
}
#endif

#endif /* SHEAF_SHEAF_H */
