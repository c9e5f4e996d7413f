// run_on_stack: work on a thread of its own with the stack asked for, errors carried back, and
// no second thread for work already on such a stack.
#include "core/base/stack.h"

#include <gtest/gtest.h>

#include <pthread.h>

#include <stdexcept>
#include <thread>

namespace sheaf {
namespace {

size_t this_threads_stack() {
    pthread_attr_t attr;
    size_t bytes = 0;
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
        pthread_attr_getstacksize(&attr, &bytes);
        pthread_attr_destroy(&attr);
    }
    return bytes;
}

TEST(RunOnStack, RunsOnAThreadWithTheStackAskedFor) {
    const std::thread::id caller = std::this_thread::get_id();
    std::thread::id ran;
    size_t stack = 0;
    run_on_stack(size_t(16) << 20, [&] {
        ran = std::this_thread::get_id();
        stack = this_threads_stack();
    });
    EXPECT_NE(ran, caller);
    EXPECT_GE(stack, size_t(16) << 20);
}

TEST(RunOnStack, WorkAlreadyOnSuchAStackRunsWhereItIs) {
    std::thread::id outer, inner, smaller;
    run_on_stack(size_t(16) << 20, [&] {
        outer = std::this_thread::get_id();
        run_on_stack(size_t(8) << 20, [&] { smaller = std::this_thread::get_id(); });
        run_on_stack(size_t(16) << 20, [&] { inner = std::this_thread::get_id(); });
    });
    EXPECT_EQ(inner, outer);
    EXPECT_EQ(smaller, outer);
    // A larger stack than the one it is on: a thread of its own again.
    std::thread::id larger;
    run_on_stack(size_t(8) << 20, [&] {
        outer = std::this_thread::get_id();
        run_on_stack(size_t(16) << 20, [&] { larger = std::this_thread::get_id(); });
    });
    EXPECT_NE(larger, outer);
}

TEST(RunOnStack, WhatTheWorkThrowsReachesTheCaller) {
    EXPECT_THROW(run_on_stack(size_t(1) << 20, [] { throw std::runtime_error("inside"); }),
                 std::runtime_error);
}

} // namespace
} // namespace sheaf
