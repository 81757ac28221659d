#include "scene/scene_test_scenes.h"

namespace glint::test {

scene::Scene analyticScene(std::uint32_t width, std::uint32_t height, std::uint32_t frames) {
    scene::Scene s;
    s.width = width;
    s.height = height;
    s.frameCount = frames;
    s.shadowSamples = 4;
    s.camera.keys = {{0.0f, {0.0f, 1.5f, 4.0f}, {0.0f, 0.4f, 0.0f}},
                     {4.0f, {0.4f, 1.4f, 3.8f}, {0.0f, 0.4f, 0.0f}}};
    scene::LightDesc sun;
    sun.direction = {0.37139f, 0.74278f, 0.55709f};
    sun.angularRadiusDegrees = 4.0f;
    s.lights.push_back(sun);
    scene::MaterialDesc floor;
    floor.name = "floor";
    floor.roughness = 0.4f;
    floor.baseColor = {0.5f, 0.5f, 0.5f};
    scene::MaterialDesc red;
    red.name = "red";
    red.baseColor = {0.8f, 0.1f, 0.1f};
    red.roughness = 0.7f;
    scene::MaterialDesc metal;
    metal.name = "metal";
    metal.metallic = 1.0f;
    metal.roughness = 0.2f;
    s.materials = {floor, red, metal};
    scene::ObjectDesc plane;
    plane.shape = scene::ShapeKind::Plane;
    plane.size = {8.0f, 0.0f, 8.0f};
    plane.material = 0;
    scene::ObjectDesc box;
    box.shape = scene::ShapeKind::Box;
    box.size = {0.7f, 0.7f, 0.7f};
    box.material = 1;
    box.keys = {{0.0f, {-0.9f, 0.35f, -0.3f}, {0.0f, 25.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}};
    scene::ObjectDesc ball;
    ball.shape = scene::ShapeKind::Sphere;
    ball.radius = 0.45f;
    ball.material = 2;
    ball.keys = {{0.0f, {0.5f, 0.45f, 0.2f}, {}, {1.0f, 1.0f, 1.0f}},
                 {4.0f, {1.3f, 0.45f, 0.2f}, {}, {1.0f, 1.0f, 1.0f}}};
    s.objects = {plane, box, ball};
    return s;
}

} // namespace glint::test
