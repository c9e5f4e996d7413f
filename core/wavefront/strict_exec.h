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
//    first, one at a time.
// Counts launches and host waits as the CPU policy does. Linux (mmap, mprotect, sigaction).
#pragma once

#include "core/base/memory.h"
#include "core/wavefront/cpu_exec.h"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <map>
#include <iterator>
#include <new>
#include <stdexcept>
#include <string>
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

class StrictExec {
  public:
    static constexpr const char* kName = "strict";
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
        strict_detail::active.store(nullptr);
    }
    StrictExec(const StrictExec&) = delete;
    StrictExec& operator=(const StrictExec&) = delete;

    void* allocate(size_t bytes) {
        const size_t used = (bytes + 15) / 16 * 16; // buffers are 16-aligned, as on a GPU
        const size_t body = (std::max<size_t>(used, 1) + page_ - 1) / page_ * page_;
        void* m = ::mmap(nullptr, body + page_, PROT_READ | PROT_WRITE,
                         MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
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

    /// fn(i) for every i in [0, n), last to first, one at a time.
    template <class Fn> void launch(const char* name, size_t n, const Fn& fn) {
        if (n == 0) return;
        ++launches_;
        Open o(*this, name);
        for (size_t i = n; i-- > 0;) fn(i);
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
        Open o(*this, name);
        return cpu_.transform_reduce(name, n, init, map, op);
    }
    template <class T, class Map, class Op>
    void reduce_into(const char* name, size_t n, T* acc, T identity, const Map& map,
                     const Op& op) {
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
    uint64_t launches() const { return cpu_.launches() + launches_; }
    uint64_t host_waits() const { return cpu_.host_waits(); }

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
    std::map<unsigned char*, Region> regions_;
    std::vector<std::string> violations_;
    MemoryTracker memory_;
    CpuExec cpu_;
    uint64_t launches_ = 0;
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
