// A CPU execution policy that holds the wavefront pipeline to a GPU's rules, for tests. What
// the CPU policy forgives and a GPU does not:
//  - the host reading or writing device memory outside a copy: every buffer is mapped
//    inaccessible between device operations, so such an access faults here as it would on the
//    GPU;
//  - reading memory the pipeline never wrote: fresh buffers hold the byte kFill, as device
//    memory holds whatever was there before (a fresh CPU allocation is often zero);
//  - indexing past a buffer's end: each buffer ends at a page the process cannot touch, and the
//    up to 15 bytes of padding before that page must still hold kFill when it is freed;
//  - depending on the order of a launch's elements: launches run their elements last to
//    first, one at a time;
//  - with seal_host(k), a launch or a reduction's map reading host memory (a captured host
//    pointer: an illegal address on the GPU): the first k runs of each launch site (each
//    lambda type) run in a forked child whose host heap and anonymous memory are inaccessible
//    but for its stack and thread-local block; device buffers are shared mappings, so the
//    child's writes are the parent's. A fork costs milliseconds, hence the per-site limit.
// Counts launches and host waits as the CPU policy does. Linux (mmap, mprotect, sigaction).
#pragma once

#include "core/base/memory.h"
#include "core/frame/cpu_exec.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sheaf::wavefront {

class StrictExec;

namespace strict_detail {

/// The StrictExec alive now (one at a time), and the device operation it runs (nullptr between
/// operations): what the fault handler consults.
inline std::atomic<StrictExec*> active{nullptr};
inline std::atomic<const char*> running{nullptr};

inline void say(const char* s) {
    const ssize_t r = ::write(2, s, std::strlen(s));
    (void)r;
}

void on_fault(int, siginfo_t* info, void*);

// A sealed child must not call a library function it has not called before: the dynamic
// linker would resolve the call lazily, with data in the sealed heap. So it writes and exits
// by system calls of its own (and the test binary links with -z now, for the math functions
// device code calls).
#if defined(__x86_64__)
inline long raw_syscall3(long nr, long a, long b, long c) {
    long r;
    asm volatile("syscall" : "=a"(r) : "a"(nr), "D"(a), "S"(b), "d"(c) : "rcx", "r11", "memory");
    return r;
}
[[noreturn]] inline void sealed_exit(int code) {
    raw_syscall3(SYS_exit_group, code, 0, 0);
    __builtin_unreachable();
}
inline void sealed_say(const char* s) {
    long n = 0;
    while (s[n]) ++n;
    raw_syscall3(SYS_write, 2, reinterpret_cast<long>(s), n);
}
#else
[[noreturn]] inline void sealed_exit(int code) { ::_exit(code); }
inline void sealed_say(const char* s) { say(s); }
#endif

/// A fault in a sealed child: says where, and ends the child.
inline void on_sealed_fault(int, siginfo_t* info, void*) {
    char hex[2 + 16 + 2] = "0x";
    auto a = reinterpret_cast<uintptr_t>(info->si_addr);
    for (int i = 17; i >= 2; --i, a >>= 4) hex[i] = "0123456789abcdef"[a & 15];
    hex[18] = '\n', hex[19] = 0;
    sealed_say("StrictExec: a sealed device operation touched host memory at ");
    sealed_say(hex);
    sealed_exit(128 + SIGSEGV);
}

inline void install_fault_handler() {
    static const bool installed = [] {
        struct sigaction sa = {};
        sa.sa_sigaction = on_fault;
        sa.sa_flags = SA_SIGINFO | SA_NODEFER;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGSEGV, &sa, nullptr);
        return true;
    }();
    (void)installed;
}

} // namespace strict_detail

/// Why seal_host cannot work in this build, or nullptr where it can. Under AddressSanitizer
/// the anonymous writable mappings a sealed child closes include the sanitizer's shadow memory,
/// which every instrumented load and store reads first, so the child faults on its first
/// access whatever the launch does. Tests that seal skip with this reason in such a build
/// (README, "What CI runs").
inline const char* sealing_unavailable() {
#if defined(__SANITIZE_ADDRESS__)
    return "sealed launches cannot run under AddressSanitizer: sealing closes its shadow memory";
#else
    return nullptr;
#endif
}

class StrictExec {
  public:
    static constexpr const char* kName = "strict";
    /// Its memory behaves as a device's: the scene is copied over, never bound.
    static constexpr bool kHostMemory = false;
    /// What fresh buffers and their padding hold.
    static constexpr unsigned char kFill = 0xA5;

    StrictExec() : page_(size_t(::sysconf(_SC_PAGESIZE))) {
        StrictExec* none = nullptr;
        if (!strict_detail::active.compare_exchange_strong(none, this))
            throw std::logic_error("one StrictExec at a time");
        strict_detail::install_fault_handler();
    }
    ~StrictExec() {
        for (auto& [p, r] : regions_) ::munmap(r.base, r.body + page_);
        if (result_) ::munmap(result_, 4096);
        strict_detail::active.store(nullptr);
    }
    StrictExec(const StrictExec&) = delete;
    StrictExec& operator=(const StrictExec&) = delete;

    void* allocate(size_t bytes) {
        const size_t used = (bytes + 15) / 16 * 16; // buffers are 16-aligned, as on a GPU
        const size_t body = (std::max<size_t>(used, 1) + page_ - 1) / page_ * page_;
        // Shared, so that what a sealed launch's child process writes is the parent's.
        void* m = ::mmap(nullptr, body + page_, PROT_READ | PROT_WRITE,
                         MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (m == MAP_FAILED) throw std::bad_alloc();
        auto* base = static_cast<unsigned char*>(m);
        std::memset(base, kFill, body);
        ::mprotect(base, body + page_, PROT_NONE); // opened by an operation's first touch
        unsigned char* p = base + body - used;
        Region& r = regions_[p];
        r.base = base, r.body = body, r.bytes = bytes, r.used = used;
        memory_.add(int64_t(bytes));
        return p;
    }
    void deallocate(void* p, size_t bytes) {
        memory_.sub(int64_t(bytes));
        const auto it = regions_.find(static_cast<unsigned char*>(p));
        if (it == regions_.end()) {
            violations_.push_back("freed a pointer that is not a buffer");
            return;
        }
        const Region& r = it->second;
        ::mprotect(r.base, r.body, PROT_READ);
        const auto* q = static_cast<const unsigned char*>(p);
        for (size_t i = r.bytes; i < r.used; ++i)
            if (q[i] != kFill) {
                violations_.push_back("a buffer of " + std::to_string(r.bytes) +
                                      " bytes was written past its end (byte " +
                                      std::to_string(i) + ")");
                break;
            }
        ::munmap(r.base, r.body + page_);
        regions_.erase(it);
    }

    void copy_to_device(void* dst, const void* src, size_t bytes) {
        Open o(*this, "copy to device");
        cpu_.copy_to_device(dst, src, bytes);
    }
    void copy_to_host(void* dst, const void* src, size_t bytes) {
        Open o(*this, "copy to host");
        cpu_.copy_to_host(dst, src, bytes);
    }
    void copy_on_device(void* dst, const void* src, size_t bytes) {
        Open o(*this, "copy on device");
        cpu_.copy_on_device(dst, src, bytes);
    }

    /// The first `runs` runs of each launch site, and of each reduction's map, run sealed
    /// from host memory (see the top of this file); 0: none.
    void seal_host(int runs) { seal_runs_ = runs; }

    /// fn(i) for every i in [0, n), last to first, one at a time.
    template <class Fn> void launch(const char* name, size_t n, const Fn& fn) {
        if (n == 0) return;
        device_launch<Fn>(name, [&] {
            for (size_t i = n; i-- > 0;) fn(i);
        });
    }

    // Elements last to first, one at a time: each takes the counter's next slots.
    template <class Count, class Fn, class Emit>
    void launch_compact(const char* name, size_t max, const Count& count, uint32_t* counter,
                        TestCount* sums, const Fn& fn, const Emit& emit) {
        if (max == 0) return;
        device_launch<Fn>(name, [&] {
            for (size_t i = std::min(max, size_t(count())); i-- > 0;) {
                const Compacted c = fn(i);
                sums->tests += c.tests, sums->hits += c.hits;
                if (!c.outputs) continue;
                const uint32_t slot = *counter;
                *counter += c.outputs;
                emit(i, c.what, slot);
            }
        });
    }
    template <class Count, class Fn>
    void launch_tally(const char* name, size_t max, const Count& count, TestCount* sums,
                      const Fn& fn) {
        if (max == 0) return;
        device_launch<Fn>(name, [&] {
            for (size_t i = std::min(max, size_t(count())); i-- > 0;) {
                const TestCount c = fn(i);
                sums->tests += c.tests, sums->hits += c.hits;
            }
        });
    }

    template <class T> T exclusive_scan(T* data, size_t n) {
        Open o(*this, "exclusive_scan");
        return cpu_.exclusive_scan(data, n);
    }
    template <class T> void exclusive_scan_async(T* data, size_t n) {
        Open o(*this, "exclusive_scan_async");
        cpu_.exclusive_scan_async(data, n);
    }
    template <class T, class Map, class Op>
    T transform_reduce(const char* name, size_t n, T init, const Map& map, const Op& op) {
        if (n > 0 && seal_next<Map>()) {
            ++launches_, ++waits_; // as the CPU policy counts
            return sealed_fold(name, n, init, map, op);
        }
        Open o(*this, name);
        return cpu_.transform_reduce(name, n, init, map, op);
    }
    template <class T, class Map, class Op>
    void reduce_into(const char* name, size_t n, T* acc, T identity, const Map& map,
                     const Op& op) {
        if (n > 0 && seal_next<Map>()) {
            launches_ += 2; // as the CPU policy counts
            const T r = sealed_fold(name, n, identity, map, op);
            Open o(*this, name);
            *acc = op(*acc, r);
            return;
        }
        Open o(*this, name);
        cpu_.reduce_into(name, n, acc, identity, map, op);
    }
    void sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n) {
        Open o(*this, "sort_pairs");
        cpu_.sort_pairs(keys, words, values, n);
    }
    void synchronize() { cpu_.synchronize(); }

    using Stopwatch = CpuExec::Stopwatch;
    Stopwatch stopwatch() { return cpu_.stopwatch(); }

    int64_t peak_bytes() const { return memory_.peak(); }
    size_t auto_batch_pairs() const { return cpu_.auto_batch_pairs(); }
    uint64_t launches() const { return cpu_.launches() + launches_; }
    uint64_t host_waits() const { return cpu_.host_waits() + waits_; }

    /// Rules broken that did not fault (writes into a buffer's padding, bad frees), checked
    /// when buffers are freed.
    const std::vector<std::string>& violations() const { return violations_; }
    /// Buffers not freed yet.
    size_t live_buffers() const { return regions_.size(); }

  private:
    friend void strict_detail::on_fault(int, siginfo_t*, void*);

    struct Region {
        unsigned char* base = nullptr;
        size_t body = 0, bytes = 0, used = 0;
        std::atomic<bool> opened{false}; // by a fault during the running operation
    };

    /// One device operation: a buffer it touches is opened by the fault handler and closed
    /// again when the operation ends, so only touched buffers cost a system call.
    class Open {
      public:
        Open(StrictExec& x, const char* name)
            : x_(x), outer_(strict_detail::running.exchange(name)) {}
        ~Open() {
            if (!outer_) x_.close_opened();
            strict_detail::running.store(outer_);
        }
        Open(const Open&) = delete;
        Open& operator=(const Open&) = delete;

      private:
        StrictExec& x_;
        const char* outer_;
    };

    /// One launch of the site whose element lambda is Fn: run() sealed from host memory when
    /// seal_host asks for it, else with the device buffers open.
    template <class Fn, class Run> void device_launch(const char* name, const Run& run) {
        ++launches_;
        if (seal_next<Fn>()) return sealed(name, run);
        Open o(*this, name);
        run();
    }

    /// Whether this run of the site whose lambda type is Fn runs sealed.
    template <class Fn> bool seal_next() {
        static const char site = 0;
        return seal_runs_ > 0 && sealed_runs_[&site]++ < seal_runs_;
    }

    /// op over map(i), i in [0, n), from init, computed in a sealed child.
    template <class T, class Map, class Op>
    T sealed_fold(const char* name, size_t n, T init, const Map& map, const Op& op) {
        static_assert(std::is_trivially_copyable_v<T> && sizeof(T) <= 4096,
                      "a reduction's value is plain data");
        if (!result_) { // a shared page the children write their reductions to
            void* m = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS,
                             -1, 0);
            if (m == MAP_FAILED) throw std::bad_alloc();
            result_ = m;
        }
        void* out = result_;
        sealed(name, [&] {
            T acc = init;
            for (size_t i = n; i-- > 0;) acc = op(acc, map(i));
            std::memcpy(out, &acc, sizeof(T));
        });
        T r;
        std::memcpy(&r, out, sizeof(T));
        return r;
    }

    /// Runs body in a forked child with every device buffer open and the host's anonymous
    /// writable memory (heap, large allocations, other threads' stacks) closed, except the
    /// calling thread's stack and thread-local block: a device lambda that reads host memory
    /// faults there. Not oneTBB in the child (its threads are not forked).
    template <class Body> void sealed(const char* name, const Body& body) {
        const pid_t pid = ::fork();
        if (pid < 0) throw std::runtime_error("StrictExec: fork failed");
        if (pid == 0) {
            struct sigaction sa = {};
            sa.sa_sigaction = strict_detail::on_sealed_fault;
            sa.sa_flags = SA_SIGINFO;
            sigemptyset(&sa.sa_mask);
            sigaction(SIGSEGV, &sa, nullptr);
            for (auto& [p, r] : regions_) ::mprotect(r.base, r.body, PROT_READ | PROT_WRITE);
            seal_host_memory();
            body();
            strict_detail::sealed_exit(0);
        }
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0))
            throw std::runtime_error(
                std::string("StrictExec: device operation '") + name +
                (WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGSEGV
                     ? "' touched host memory (a captured host pointer?)"
                     : "' failed in its sealed process (status " + std::to_string(status) +
                           ")"));
    }

    /// Closes the anonymous private writable mappings but the ones holding this thread's
    /// stack and errno (its thread-local block), and those that continue a file's mapping (a
    /// library's .bss). Reads /proc/self/maps with system calls into the stack only.
    static void seal_host_memory() {
        struct Range {
            uintptr_t lo, hi;
        };
        static constexpr int kMax = 8192;
        Range closing[kMax];
        int count = 0;
        char buf[1 << 16];
        size_t have = 0;
        const int fd = ::open("/proc/self/maps", O_RDONLY);
        if (fd < 0) strict_detail::sealed_exit(3);
        const uintptr_t stack = reinterpret_cast<uintptr_t>(&buf);
        const uintptr_t tls = reinterpret_cast<uintptr_t>(&errno);
        uintptr_t file_end = 0; // the end of the last file-backed mapping
        bool eof = false;
        for (;;) {
            char* nl = static_cast<char*>(std::memchr(buf, '\n', have));
            if (!nl) { // read more only when no whole line is left
                if (eof || have == sizeof buf) break;
                const ssize_t got = ::read(fd, buf + have, sizeof buf - have);
                if (got <= 0) eof = true;
                else have += size_t(got);
                continue;
            }
            // lo-hi perms offset dev inode [path]
            const char* c = buf;
            auto hex = [&c] {
                uintptr_t v = 0;
                for (;; ++c) {
                    const char h = *c;
                    if (h >= '0' && h <= '9') v = v * 16 + uintptr_t(h - '0');
                    else if (h >= 'a' && h <= 'f') v = v * 16 + uintptr_t(h - 'a' + 10);
                    else break;
                }
                return v;
            };
            const uintptr_t lo = hex();
            ++c;
            const uintptr_t hi = hex();
            ++c;
            const bool writable = c[1] == 'w', shared = c[3] == 's';
            int field = 0; // after perms: offset, dev, inode, then the path
            const char* path = nullptr;
            for (const char* q = c; q < nl; ++q)
                if (*q == ' ' && q + 1 < nl && q[1] != ' ' && ++field == 4) path = q + 1;
            const bool named = path && path < nl;
            const bool file = named && *path == '/';
            const bool heap = named && std::strncmp(path, "[heap]", 6) == 0;
            if (file) file_end = hi;
            else if (writable && !shared && (heap || !named) && lo != file_end &&
                     !(stack >= lo && stack < hi) && !(tls >= lo && tls < hi) && count < kMax)
                closing[count++] = Range{lo, hi};
            const size_t line = size_t(nl - buf) + 1;
            std::memmove(buf, nl + 1, have - line);
            have -= line;
        }
        ::close(fd);
        for (int i = 0; i < count; ++i)
            ::mprotect(reinterpret_cast<void*>(closing[i].lo), closing[i].hi - closing[i].lo,
                       PROT_NONE);
    }

    void close_opened() {
        for (auto& [p, r] : regions_)
            if (r.opened.exchange(false)) ::mprotect(r.base, r.body, PROT_NONE);
    }

    /// The region whose mapping (body and guard page) holds `a`, or nullptr. Reads the map
    /// only: the host thread changes it between operations, never during one.
    Region* region_at(const unsigned char* a) {
        auto it = regions_.upper_bound(const_cast<unsigned char*>(a));
        if (it != regions_.end()) { // the next buffer's body may begin on a's page
            const Region& r = it->second;
            if (a >= r.base && a < r.base + r.body + page_) return &it->second;
        }
        if (it == regions_.begin()) return nullptr;
        Region& r = std::prev(it)->second;
        return a >= r.base && a < r.base + r.body + page_ ? &r : nullptr;
    }

    size_t page_;
    int seal_runs_ = 0;
    std::map<const char*, int> sealed_runs_;
    void* result_ = nullptr;
    std::map<unsigned char*, Region> regions_;
    std::vector<std::string> violations_;
    MemoryTracker memory_;
    CpuExec cpu_;
    uint64_t launches_ = 0, waits_ = 0;
};

namespace strict_detail {

/// A memory fault while a StrictExec is alive. Inside a device operation, on a buffer's body:
/// the operation's first touch, which opens the buffer. Anything else breaks a rule: say which,
/// then let the fault happen again under the default action, so the process dies as it would
/// have.
inline void on_fault(int, siginfo_t* info, void*) {
    StrictExec* x = active.load();
    const char* op = running.load();
    const auto* a = static_cast<const unsigned char*>(info->si_addr);
    StrictExec::Region* r = x ? x->region_at(a) : nullptr;
    if (r && op) {
        if (a < r->base + r->body) {
            ::mprotect(r->base, r->body, PROT_READ | PROT_WRITE);
            r->opened.store(true);
            return;
        }
        say("StrictExec: memory fault inside device operation '");
        say(op);
        say("': an index past a buffer's end\n");
    } else if (r) {
        say("StrictExec: memory fault between device operations: the host touched device "
            "memory\n");
    } else if (x && op) {
        say("StrictExec: memory fault inside device operation '");
        say(op);
        say("', not in a live buffer (a freed buffer, or host memory)\n");
    }
    ::signal(SIGSEGV, SIG_DFL);
}

} // namespace strict_detail

} // namespace sheaf::wavefront
