// The module's one headless GL context and renderer, made on first use and
// kept for the life of the process (a Dask worker, a notebook): later calls
// skip the context and shader setup. One thread draws at a time; the
// context is current on the drawing thread only while a call draws.
#pragma once

#include "render/renderer.h"

#include <memory>
#include <mutex>
#include <string>

namespace kappa::python {

struct GlStats {
    std::string description;  // "" before the first drawing
    int contexts_created = 0;
    long drawings = 0;        // calls that drew
};

// Holds the context current on this thread while alive (waits for others).
class CurrentRenderer {
public:
    CurrentRenderer();  // throws render::ContextError
    ~CurrentRenderer();
    CurrentRenderer(const CurrentRenderer&) = delete;
    CurrentRenderer& operator=(const CurrentRenderer&) = delete;
    render::Renderer& renderer();

private:
    std::unique_lock<std::mutex> lock_;
};

GlStats gl_stats();

}  // namespace kappa::python
