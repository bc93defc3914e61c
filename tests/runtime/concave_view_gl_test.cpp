// View rays that leave an object and enter it again (issue 13): ss integrates
// the Gaussians only over the intervals the ray spends inside, and the view
// attenuation counts only those, as the reference does exactly. Two shapes
// with a known answer: two spheres in one mesh, one behind the other, and a U
// seen through its gap. Held to ss's goal for their optical radius.
#include <gtest/gtest.h>

#include <fstream>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// The unit sphere's mesh at each (centre, radius), as one OBJ.
std::string spheresObj(const std::vector<std::pair<Vec3, double>>& spheres) {
    std::vector<std::string> lines;
    std::ifstream in(test::modelsDir() / "sphere.obj");
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string obj;
    size_t offset = 0;
    for (const auto& [centre, radius] : spheres) {
        size_t vertices = 0;
        for (const std::string& line : lines) {
            if (line.rfind("v ", 0) == 0) {
                double x, y, z;
                std::sscanf(line.c_str() + 2, "%lf %lf %lf", &x, &y, &z);
                const Vec3 p = centre + radius * Vec3(x, y, z);
                char text[128];
                std::snprintf(text, sizeof text, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
                obj += text;
                ++vertices;
            } else if (line.rfind("f ", 0) == 0) {
                unsigned a, b, c;
                std::sscanf(line.c_str() + 2, "%u %u %u", &a, &b, &c);
                obj += "f " + std::to_string(a + offset) + " " + std::to_string(b + offset) + " " +
                       std::to_string(c + offset) + "\n";
            }
        }
        offset += vertices;
    }
    return obj;
}

// A U in the xy plane (outer [-1, 1]^2, a gap |x| < 0.4 above y = -0.2),
// extruded over |z| < 0.5; the caps split into rectangles with no T-junction.
std::string uObj() {
    const double u[10][2] = {{-1, -1},    {1, -1},      {1, -0.2}, {1, 1},  {0.4, 1},
                             {0.4, -0.2}, {-0.4, -0.2}, {-0.4, 1}, {-1, 1}, {-1, -0.2}};
    std::string obj;
    for (double z : {-0.5, 0.5})
        for (const auto& p : u)
            obj += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(z) + "\n";
    // Counter-clockwise in xy: the z = 0.5 cap (vertices 11-20) faces +z.
    const int cap[8][3] = {{0, 1, 2}, {0, 2, 5}, {0, 5, 6}, {0, 6, 9}, {9, 6, 7}, {9, 7, 8}, {5, 2, 3}, {5, 3, 4}};
    auto face = [&](int a, int b, int c) {
        obj += "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " + std::to_string(c + 1) + "\n";
    };
    for (const auto& t : cap) {
        face(10 + t[0], 10 + t[1], 10 + t[2]);
        face(t[0], t[2], t[1]);
    }
    for (int i = 0; i < 10; ++i) {
        const int j = (i + 1) % 10;
        face(i, j, 10 + j);
        face(i, 10 + j, 10 + i);
    }
    return obj;
}

struct Shape {
    const char* name;
    std::string obj;
    Vec3 camera, target, light;
};

class ConcaveView : public ::testing::TestWithParam<int> {};

TEST_P(ConcaveView, MeetsTheGoalThroughTheAirBetweenItsParts) {
    const Shape shapes[] = {
        {"two spheres, one behind the other", spheresObj({{Vec3(0, 0, 0.8), 0.5}, {Vec3(0, 0, -0.8), 0.5}}),
         Vec3(0.3, 0.2, 6.0), Vec3(0, 0, 0), Vec3(3, 3, 0)},
        {"a U seen through its gap", uObj(), Vec3(-6.0, 0.5, 0.8), Vec3(0, 0.2, 0), Vec3(0.5, 5.0, 3.0)},
    };
    const Shape& shape = shapes[GetParam()];
    test::ScratchDir dir;
    SceneDesc scene;
    scene.camera = test::squareCamera(shape.camera, shape.target, 30, 96);
    scene.lights = {test::pointLight(shape.light, Rgb(40.0))};
    ObjectDesc o = test::simpleObject(dir.write("shape.obj", shape.obj), 2.0, 0.75);
    o.samples = dir.path() / "shape.lsf";
    scene.objects = {o};
    const ImageError e = test::ssAgainstReference(scene);
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    std::printf("%s: relative RMSE %.4f, mean ratio %.4f\n", shape.name, e.relativeRmse, e.meanRatio);
    EXPECT_GT(e.pixels, 500u);
    EXPECT_LT(e.relativeRmse, test::ssGoalRelativeRmse(objects));
}

INSTANTIATE_TEST_SUITE_P(Shapes, ConcaveView, ::testing::Values(0, 1));

}  // namespace
}  // namespace lucent
