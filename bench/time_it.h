// Timing loop shared by the benchmarks that time one function at a time.
#pragma once

#include "median.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <vector>

namespace kappa::bench {

// Runs `body` once untimed (warm-up), then `runs` timed times; prints each
// wall time, then the medians of wall time and of process CPU time (all
// threads; less sensitive to other load on a shared machine). `setup`, when
// given, runs untimed before each run of body (fresh inputs for it).
inline void time_it(const char* label, int runs, const std::function<void()>& body, int label_width = 24,
                    const std::function<void()>& setup = {}) {
    if (setup) setup();
    body();
    std::vector<double> ms, cpu_ms;
    std::printf("%-*s", label_width, label);
    for (int r = 0; r < runs; ++r) {
        if (setup) setup();
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        body();
        cpu_ms.push_back(1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        std::printf(" %.1f", ms.back());
    }
    std::printf("  | median %.2f ms wall, %.2f ms cpu\n", median(ms), median(cpu_ms));
    std::fflush(stdout);
}

}  // namespace kappa::bench
