#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace kappa {

namespace {
std::atomic<unsigned> g_threads{0};
}

void set_thread_count(unsigned n) { g_threads = n; }

unsigned thread_count() {
    unsigned n = g_threads;
    static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());  // reads /sys each call
    if (n == 0) n = hardware;
    return n;
}

void parallel_for_ranges(size_t n, const std::function<void(size_t, size_t)>& body,
                         size_t min_chunk) {
    if (n == 0) return;
    size_t threads = std::min<size_t>(thread_count(), (n + min_chunk - 1) / std::max<size_t>(min_chunk, 1));
    if (threads <= 1) {
        body(0, n);
        return;
    }
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    size_t chunk = (n + threads - 1) / threads;
    for (size_t t = 1; t < threads; ++t) {
        size_t b = t * chunk, e = std::min(n, b + chunk);
        if (b < e) workers.emplace_back([&body, b, e] { body(b, e); });
    }
    body(0, std::min(n, chunk));
    for (auto& w : workers) w.join();
}

void parallel_for_chunks(size_t n, const std::function<void(size_t, size_t)>& body, size_t chunk) {
    if (n == 0) return;
    chunk = std::max<size_t>(chunk, 1);
    const size_t chunks = (n + chunk - 1) / chunk;
    const size_t threads = std::min<size_t>(thread_count(), chunks);
    if (threads <= 1) {
        body(0, n);
        return;
    }
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t c = next++; c < chunks; c = next++) body(c * chunk, std::min(n, (c + 1) * chunk));
    };
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    for (size_t t = 1; t < threads; ++t) workers.emplace_back(work);
    work();
    for (auto& w : workers) w.join();
}

void parallel_for_dynamic(size_t n, const std::function<void(size_t)>& body) {
    parallel_for_chunks(
        n, [&](size_t b, size_t e) { for (size_t i = b; i < e; ++i) body(i); }, 1);
}

}  // namespace kappa
