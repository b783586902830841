// kappa view frames a model on the up axis of its default view, as kappa
// render does (geometry/view/default_view.h): a bust standing z-up on a flat
// base opens upright, not lying on its side about +y.
#include <catch2/catch.hpp>

#include "render/camera/camera.h"
#include "test_shapes.h"
#include "test_support.h"
#include "test_upright_shapes.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>


using namespace kappa;

TEST_CASE("kappa view opens a z-up bust upright, on the up axis kappa render uses", "[viewer][window]") {
    const Mesh bust = test::bust_z_up();
    const std::string dir = test::temp_dir();
    test::write_off(dir + "/bust.off", bust);
    test::write_file(dir + "/steps.txt", "frames 2\nsave-view " + dir + "/start.xf\n");
    const auto run = test::run_under_xvfb(std::string(KAPPA_EXE) + " view " + dir + "/bust.off --size 400x300 --script " +
                                          dir + "/steps.txt");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const glm::mat4 view = render::read_xf(dir + "/start.xf");
    const glm::mat4 to_model = glm::inverse(view);
    const glm::vec3 image_up = glm::normalize(glm::vec3(to_model * glm::vec4(0, 1, 0, 0)));
    const glm::vec3 towards_eye = glm::normalize(glm::vec3(to_model * glm::vec4(0, 0, 1, 0)));
    INFO("image up in model coordinates " << image_up.x << "," << image_up.y << "," << image_up.z);
    // Seen from 20-35 degrees above the base's plane, +z up in the image: no roll about the view.
    CHECK(image_up.z > 0.8f);
    CHECK(std::abs(glm::dot(glm::cross(towards_eye, image_up), glm::vec3(0, 0, 1))) < 1e-3f);
    CHECK(towards_eye.z > 0.3f);
}
