// How well two line drawings agree (render/image/ink_agreement.h): the fraction of
// the first image's ink within R pixels of the second's, and back, and the
// ink counts. Used by bench/compare_rtsc.sh to compare kappa with rtsc.
//
//   build/bench_render_agreement A.png B.png [R]     (R: 2 pixels by default)
// prints: A_within_B B_within_A ink_A ink_B
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

using namespace kappa;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s A.png B.png [radius px]\n", argv[0]);
        return 2;
    }
    try {
        const render::Image a = render::read_png(argv[1]), b = render::read_png(argv[2]);
        if (a.width != b.width || a.height != b.height) {
            std::fprintf(stderr, "%s and %s differ in size\n", argv[1], argv[2]);
            return 1;
        }
        const float radius = argc > 3 ? float(std::atof(argv[3])) : 2.0f;
        std::printf("%.3f %.3f %zu %zu\n", render::ink_within(a, b, radius), render::ink_within(b, a, radius),
                    render::count_ink(a), render::count_ink(b));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
