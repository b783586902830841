// Work cut into steps that run one at a time, for callers that spread it
// over time: the browser page has one thread and prepares a view's fields
// between its frames (render/fields/detail_fields_job.h). A step may take
// several calls (it says when it is finished) and may add steps after it.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>

namespace kappa {

class StepQueue {
public:
    using Step = std::function<bool()>;  // returns whether it is finished

    void add(Step step) { steps_.push_back(std::move(step)); }
    // A step that runs `body` once.
    void add_once(std::function<void()> body) {
        add([body = std::move(body)] {
            body();
            return true;
        });
    }
    // Steps calling body(first, last) over [0, n), `chunk` indices each (0: one step).
    void add_chunks(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body) {
        const size_t size = chunk == 0 ? (n > 0 ? n : 1) : chunk;
        for (size_t first = 0; first < n; first += size)
            add_once([body, first, last = first + size < n ? first + size : n] { body(first, last); });
    }
    bool done() const { return steps_.empty(); }
    // The next step (nothing once done).
    void step() {
        if (!done() && steps_.front()()) steps_.pop_front();
    }
    // Steps until done or until `seconds` have passed (at least one step); returns done().
    bool run_for(double seconds) {
        const auto start = std::chrono::steady_clock::now();
        do step();
        while (!done() && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds);
        return done();
    }

private:
    std::deque<Step> steps_;
};

}  // namespace kappa
