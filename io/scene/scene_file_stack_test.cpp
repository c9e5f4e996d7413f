// Readers run on a stack of their own (core/base/stack.h): the deepest hostile scenes load or
// fail with their error from a calling thread with a 256 KiB stack, where the reader's
// recursion on the caller's stack would overflow it.
#include "io/scene/scene_file.h"

#include "core/base/error.h"
#include "core/base/stack.h"

#include <gtest/gtest.h>

#include <pthread.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace sheaf {
namespace {

/// Runs fn on a thread with `bytes` of stack, as a host's small-stack thread would.
void on_small_thread(size_t bytes, const std::function<void()>& fn) {
    pthread_attr_t attr;
    ASSERT_EQ(pthread_attr_init(&attr), 0);
    ASSERT_EQ(pthread_attr_setstacksize(&attr, bytes), 0);
    pthread_t t;
    auto run = [](void* p) -> void* {
        (*static_cast<const std::function<void()>*>(p))();
        return nullptr;
    };
    ASSERT_EQ(pthread_create(&t, &attr, run, const_cast<std::function<void()>*>(&fn)), 0);
    pthread_join(t, nullptr);
    pthread_attr_destroy(&attr);
}

TEST(SceneFileStack, DeepScenesLoadFromAThreadWithASmallStack) {
    const std::string dir = std::string(SHEAF_SCENES_DIR) + "/../tests/fuzz/regressions/";
    for (const char* name : {"pov_deep_parentheses.pov", "pov_deep_unary.pov", "pov_deep_csg.pov",
                             "pov_deep_vectors.pov", "pov_deep_pigments.pov",
                             "pov_deep_macro_arguments.pov"}) {
        std::string outcome;
        on_small_thread(256 << 10, [&] {
            try {
                io::load_scene_file(dir + name);
                outcome = "loaded";
            } catch (const SceneError& e) {
                outcome = e.what();
            } catch (const std::exception& e) {
                outcome = std::string("unexpected: ") + e.what();
            }
        });
        EXPECT_FALSE(outcome.empty()) << name;
        EXPECT_EQ(outcome.find("unexpected"), std::string::npos) << name << ": " << outcome;
    }
}

TEST(SceneFileStack, RunOnStackPassesResultsAndErrorsBack) {
    int depth = 0;
    std::function<int(int)> down = [&](int n) { return n == 0 ? 0 : 1 + down(n - 1); };
    run_on_stack(kReaderStackBytes, [&] { depth = down(20000); });
    EXPECT_EQ(depth, 20000);
    EXPECT_THROW(run_on_stack(1 << 20, [] { throw SceneError("a reader's error"); }), SceneError);
}

} // namespace
} // namespace sheaf
