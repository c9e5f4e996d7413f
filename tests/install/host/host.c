/* A host built against an installed Sheaf (tests/install): prints the version it was compiled
 * with and the one it runs with, renders the default built-in scene small and saves it as
 * argv[1] (which needs the image module installed beside libsheaf), and prints a hash of the
 * frame's pixels. Exits non-zero on failure. */
#include <sheaf/sheaf.h>
#include <sheaf/sheaf_version.h>

#include <stdint.h>
#include <stdio.h>
#include <string.h>

static int ok(SheafError e, const char* what) {
    const char* message = NULL;
    if (e == SHEAF_OK) return 1;
    sheafGetLastError(&message);
    fprintf(stderr, "%s: %s\n", what, message ? message : "failed");
    return 0;
}

int main(int argc, char** argv) {
    SheafScene scene = NULL;
    SheafRenderer renderer = NULL;
    SheafFrame frame = NULL;
    int good;
    if (argc < 2) {
        fprintf(stderr, "usage: host OUT.png\n");
        return 2;
    }
    printf("compiled against %s, running %s\n", SHEAF_VERSION_STRING, sheafGetVersionString());
    good = ok(sheafSceneNew(&scene), "sheafSceneNew") &&
           ok(sheafSceneLoadBuiltin(scene, sheafGetDefaultSceneName()), "sheafSceneLoadBuiltin") &&
           ok(sheafRendererNew(&renderer), "sheafRendererNew") &&
           ok(sheafRendererSetInt(renderer, "width", 64), "width") &&
           ok(sheafRendererSetInt(renderer, "height", 48), "height") &&
           ok(sheafRender(renderer, scene, &frame), "sheafRender") &&
           ok(sheafFrameSaveImage(frame, argv[1]), "sheafFrameSaveImage");
    if (renderer) sheafRendererRelease(renderer);
    if (scene) sheafSceneRelease(scene);
    if (good) {
        /* FNV-1a over the colour pass's bytes: equal frames print the same line. */
        static float rgba[64 * 48 * 4];
        uint64_t hash = 1469598103934665603ull;
        size_t i;
        unsigned char bytes[sizeof rgba[0]];
        good = ok(sheafFrameGetPass(frame, "combined", rgba, sizeof rgba / sizeof rgba[0]),
                  "sheafFrameGetPass");
        for (i = 0; good && i < sizeof rgba / sizeof rgba[0]; ++i) {
            size_t b;
            memcpy(bytes, &rgba[i], sizeof bytes);
            for (b = 0; b < sizeof bytes; ++b) hash = (hash ^ bytes[b]) * 1099511628211ull;
        }
        if (good) printf("wrote %s, pixels %016llx\n", argv[1], (unsigned long long)hash);
    }
    if (frame) sheafFrameRelease(frame);
    return good ? 0 : 1;
}
