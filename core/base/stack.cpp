#include "core/base/stack.h"

#include <pthread.h>

#include <exception>

namespace sheaf {

namespace {

struct Job {
    const std::function<void()>* fn;
    size_t bytes;
    std::exception_ptr error;
};

/// The stack this thread was started with by run_on_stack; 0 for any other thread.
thread_local size_t t_stack_bytes = 0;

void* run_job(void* p) {
    Job& job = *static_cast<Job*>(p);
    t_stack_bytes = job.bytes;
    try {
        (*job.fn)();
    } catch (...) {
        job.error = std::current_exception();
    }
    return nullptr;
}

} // namespace

void run_on_stack(size_t bytes, const std::function<void()>& fn) {
    if (t_stack_bytes >= bytes) { // already on such a stack (a reader inside the dispatcher)
        fn();
        return;
    }
    Job job{&fn, bytes, nullptr};
    pthread_attr_t attr;
    bool started = false;
    pthread_t thread;
    if (pthread_attr_init(&attr) == 0) {
        started = pthread_attr_setstacksize(&attr, bytes) == 0 &&
                  pthread_create(&thread, &attr, run_job, &job) == 0;
        pthread_attr_destroy(&attr);
    }
    if (!started) { // no thread to be had: the caller's stack, as before
        fn();
        return;
    }
    pthread_join(thread, nullptr);
    if (job.error) std::rethrow_exception(job.error);
}

} // namespace sheaf
