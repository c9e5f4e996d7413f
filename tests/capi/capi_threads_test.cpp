// The C ABI from several threads at once (docs/capi.md, "Threading"): different scenes each
// with its own renderer, one committed scene shared by two renderers, a render cancelled from
// another thread while others go on, and errors kept per thread. Every image must equal,
// bit for bit, the same frame rendered alone. Exits non-zero on any failure.
// Built with -fsanitize=thread it is also the ThreadSanitizer check (docs/capi.md says what ran).
#include <sheaf/sheaf.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

std::atomic<int> g_failures{0};

void fail(const std::string& what) {
    ++g_failures;
    std::fprintf(stderr, "FAILED: %s\n", what.c_str());
}

bool ok(SheafError e, const std::string& what) {
    if (e == SHEAF_OK) return true;
    const char* message = nullptr;
    sheafGetLastError(&message);
    fail(what + ": " + (message ? message : "?"));
    return false;
}

struct Job {
    std::string scene;   // builtin:NAME or a file
    std::string accel;   // the renderer's accel setting
    int width, height;
};

SheafScene load(const std::string& name) {
    SheafScene s = nullptr;
    if (!ok(sheafSceneNew(&s), "sheafSceneNew")) return nullptr;
    const bool builtin = name.rfind("builtin:", 0) == 0;
    const SheafError e = builtin ? sheafSceneLoadBuiltin(s, name.c_str() + 8)
                                 : sheafSceneLoadFile(s, name.c_str());
    if (!ok(e, "load " + name) || !ok(sheafSceneCommit(s), "commit " + name)) {
        sheafSceneRelease(s);
        return nullptr;
    }
    return s;
}

SheafRenderer renderer_for(const Job& j) {
    SheafRenderer r = nullptr;
    if (!ok(sheafRendererNew(&r), "sheafRendererNew")) return nullptr;
    ok(sheafRendererSetInt(r, "width", j.width), "width");
    ok(sheafRendererSetInt(r, "height", j.height), "height");
    ok(sheafRendererSetString(r, "accel", j.accel.c_str()), "accel");
    ok(sheafRendererSetInt(r, "threads", 2), "threads");
    return r;
}

/// The frame's colour pass, or empty when the render failed.
std::vector<float> render(SheafRenderer r, SheafScene s, const std::string& what) {
    SheafFrame f = nullptr;
    if (!ok(sheafRender(r, s, &f), "render " + what)) return {};
    int w = 0, h = 0;
    sheafFrameGetSize(f, &w, &h);
    std::vector<float> rgba(size_t(w) * size_t(h) * 4);
    ok(sheafFrameGetPass(f, "combined", rgba.data(), rgba.size()), "pass " + what);
    sheafFrameRelease(f);
    return rgba;
}

std::vector<float> render_alone(const Job& j) {
    SheafScene s = load(j.scene);
    SheafRenderer r = renderer_for(j);
    std::vector<float> px = s && r ? render(r, s, j.scene) : std::vector<float>{};
    if (r) sheafRendererRelease(r);
    if (s) sheafSceneRelease(s);
    return px;
}

void expect_same(const std::vector<float>& got, const std::vector<float>& want,
                 const std::string& what) {
    if (got.empty() || got.size() != want.size() ||
        std::memcmp(got.data(), want.data(), got.size() * sizeof(float)) != 0)
        fail(what + ": the image differs from the same frame rendered alone");
}

struct Cancel {
    std::atomic<bool> started{false}; // the render reported progress
    std::atomic<bool> cancel{false};  // set by another thread
};

int on_progress(void* user, float) {
    auto* c = static_cast<Cancel*>(user);
    c->started = true;
    return c->cancel ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    const std::string scenes = argc > 1 ? argv[1] : "scenes";
    const std::vector<Job> jobs = {
        {"builtin:cornell", "crsh", 96, 72},
        {"builtin:office", "bvh", 96, 72},
        {"builtin:colonnade", "crsh", 80, 60},
        {scenes + "/lights.pov", "crsh", 96, 72},
    };
    std::vector<std::vector<float>> alone;
    for (const Job& j : jobs) alone.push_back(render_alone(j));

    // 1. Each thread its own scene and renderer, all at once, twice over.
    {
        std::vector<std::thread> threads;
        for (int round = 0; round < 2; ++round)
            for (size_t i = 0; i < jobs.size(); ++i)
                threads.emplace_back([&, i] {
                    expect_same(render_alone(jobs[i]), alone[i], "concurrent " + jobs[i].scene);
                });
        for (std::thread& t : threads) t.join();
    }

    // 2. One committed scene, two renderers (crsh and bvh give the same image), at once.
    {
        const Job crsh = {"builtin:office", "crsh", 96, 72};
        const std::vector<float> want = render_alone(crsh);
        SheafScene shared = load(crsh.scene);
        std::vector<std::thread> threads;
        for (int i = 0; i < 4; ++i)
            threads.emplace_back([&, i] {
                Job j = crsh;
                j.accel = i % 2 ? "bvh" : "crsh";
                SheafRenderer r = renderer_for(j);
                if (r && shared) {
                    expect_same(render(r, shared, "shared office"), want,
                                "a shared scene under " + j.accel);
                    sheafRendererRelease(r);
                }
            });
        for (std::thread& t : threads) t.join();
        if (shared) sheafSceneRelease(shared);
    }

    // 3. A render cancelled from another thread while another render goes on; the cancelled
    //    renderer then renders its frame again, whole.
    {
        const Job big = {"builtin:office", "crsh", 320, 240};
        const std::vector<float> want = render_alone(big);
        SheafScene scene = load(big.scene);
        SheafRenderer r = renderer_for(big);
        Cancel c;
        ok(sheafRendererSetProgressCallback(r, on_progress, &c), "progress callback");
        std::thread other([&] {
            expect_same(render_alone(jobs[0]), alone[0], "a render beside a cancelled one");
        });
        std::thread canceller([&] {
            while (!c.started) std::this_thread::yield();
            c.cancel = true;
        });
        SheafFrame f = nullptr;
        const SheafError e = sheafRender(r, scene, &f);
        canceller.join();
        other.join();
        if (e != SHEAF_ERROR_CANCELLED) fail("a cancelled render returned " + std::to_string(e));
        if (f) fail("a cancelled render handed back a frame");
        c.cancel = false;
        expect_same(render(r, scene, "after a cancel"), want, "the render after a cancel");
        sheafRendererRelease(r);
        sheafSceneRelease(scene);
    }

    // 4. Errors are per thread: one thread's failure is not another's message. Each thread
    //    makes its failing call, waits until the other has made its own, then reads its error.
    {
        std::atomic<int> ready{0};
        const auto error_after = [&](void (*failing_call)(), std::string& message) {
            failing_call();
            ++ready;
            while (ready < 2) std::this_thread::yield();
            const char* m = nullptr;
            sheafGetLastError(&m);
            message = m ? m : "";
        };
        std::string message_a, message_b;
        // Failing calls that leave nothing to release: a later successful call would clear
        // the thread's error before it is read.
        std::thread a(error_after, +[] {
            const char* name = nullptr;
            sheafGetBuiltinSceneName(999, &name); // an index out of range
        }, std::ref(message_a));
        std::thread b(error_after, +[] {
            sheafRendererSetInt(nullptr, "width", 64); // no renderer
        }, std::ref(message_b));
        a.join();
        b.join();
        if (message_a.find("999") == std::string::npos)
            fail("thread a's error is '" + message_a + "'");
        if (message_b.find("'renderer'") == std::string::npos)
            fail("thread b's error is '" + message_b + "'");
    }

    if (g_failures) {
        std::fprintf(stderr, "%d failures\n", g_failures.load());
        return 1;
    }
    std::printf("capi_threads: every concurrent frame equals the frame rendered alone\n");
    return 0;
}
