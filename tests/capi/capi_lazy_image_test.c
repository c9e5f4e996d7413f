/* Start-up: libsheaf loads OpenImageIO (through its image module, libsheaf_image.so.0) only at
 * the first image that needs it. A host that loads a scene, renders into memory and saves a PNG
 * (libpng) never maps it; the first EXR saved maps it and writes a readable file. Exits
 * non-zero on any failure. */
#include <sheaf/sheaf.h>

#include <stdio.h>
#include <string.h>

#include "check.h"

/* Whether a library whose path contains `name` is mapped into this process. */
static int mapped(const char* name) {
    char line[4096];
    int found = 0;
    FILE* maps = fopen("/proc/self/maps", "r");
    if (!maps) {
        fprintf(stderr, "cannot read /proc/self/maps\n");
        return -1;
    }
    while (!found && fgets(line, sizeof line, maps)) found = strstr(line, name) != NULL;
    fclose(maps);
    return found;
}

/* Whether the file at `path` begins with the `n` bytes of `magic`. */
static int starts_with(const char* path, const char* magic, size_t n) {
    unsigned char head[8] = {0};
    FILE* f = fopen(path, "rb");
    int same;
    if (!f) return 0;
    same = n <= sizeof head && fread(head, 1, n, f) == n && memcmp(head, magic, n) == 0;
    fclose(f);
    return same;
}

int main(int argc, char** argv) {
    SheafScene scene = NULL;
    SheafRenderer renderer = NULL;
    SheafFrame frame = NULL;
    const char* out = argc > 1 ? argv[1] : "capi_lazy_image.png";
    const char* exr = argc > 2 ? argv[2] : "capi_lazy_image.exr";
    int width = 0, height = 0;

    CHECK(mapped("libOpenImageIO") == 0, "OpenImageIO mapped at load");
    OK(sheafSceneNew(&scene));
    OK(sheafSceneLoadBuiltin(scene, "cornell"));
    OK(sheafRendererNew(&renderer));
    OK(sheafRendererSetInt(renderer, "width", 32));
    OK(sheafRendererSetInt(renderer, "height", 24));
    OK(sheafRender(renderer, scene, &frame));
    OK(sheafFrameGetSize(frame, &width, &height));
    CHECK(width == 32 && height == 24, "a frame of %dx%d", width, height);
    CHECK(mapped("libOpenImageIO") == 0, "OpenImageIO mapped by a render into memory");
    CHECK(mapped("libsheaf_image") == 0, "the image module loaded by a render into memory");

    remove(out);
    OK(sheafFrameSaveImage(frame, out)); /* a PNG: written with libpng, no module */
    CHECK(mapped("libsheaf_image") == 0, "a PNG loaded the image module");
    CHECK(mapped("libOpenImageIO") == 0, "a PNG loaded OpenImageIO");
    CHECK(starts_with(out, "\x89PNG\r\n\x1a\n", 8), "%s is not a PNG file", out);

    remove(exr);
    OK(sheafFrameSaveImage(frame, exr));
    CHECK(mapped("libsheaf_image") == 1, "the first EXR saved did not load the image module");
    CHECK(mapped("libOpenImageIO") == 1, "the first EXR saved did not load OpenImageIO");
    CHECK(starts_with(exr, "\x76\x2f\x31\x01", 4), "%s is not an OpenEXR file", exr);

    /* An unknown extension is refused with Sheaf's message, as before the module. */
    CHECK(sheafFrameSaveImage(frame, "x.unknown") == SHEAF_ERROR_IO,
          "x.unknown was not refused as an I/O error");

    OK(sheafFrameRelease(frame));
    OK(sheafRendererRelease(renderer));
    OK(sheafSceneRelease(scene));
    if (g_failures)
        fprintf(stderr, "%d failures\n", g_failures);
    else
        printf("capi_lazy_image: all %d checks passed\n", g_checks);
    return g_failures ? 1 : 0;
}
