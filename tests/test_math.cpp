// Quaternion and matrix maths of seed 002 eq. 52-54 against values computed by hand.
#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "math/transform.hpp"

using namespace fxview::math;

namespace {
// Float products of a handful of terms: 1e-6 is a few ulps at magnitude 1.
constexpr float kTight = 1e-6f;

void check_matrix(const glm::mat4& actual, const float (&expected_rows)[4][4], float tolerance = kTight) {
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
            CAPTURE(row);
            CAPTURE(column);
            CHECK(std::abs(actual[column][row] - expected_rows[row][column]) <= tolerance);
        }
}
}  // namespace

TEST_CASE("rotation matrix is eq. 52 transposed (column vectors)") {
    // q = (w, x, y, z) = (0.5, 0.5, 0.5, 0.5): 120 degrees about (1,1,1), which cycles x -> y -> z.
    // Eq. 52 element by element: w^2+x^2-y^2-z^2 = 0, 2xy+2wz = 1, 2xz-2wy = 0, ...
    // gives the row-vector matrix [[0,1,0],[0,0,1],[1,0,0]]; its transpose acts on column vectors.
    const glm::quat q(0.5f, 0.5f, 0.5f, 0.5f);
    const float expected[4][4] = {{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
    check_matrix(rotation_matrix(q), expected);
    const glm::vec4 x_axis = rotation_matrix(q) * glm::vec4(1, 0, 0, 0);
    CHECK(x_axis.y == doctest::Approx(1.0f));  // x -> y

    // 90 degrees about Z: w = cos 45, z = sin 45. Eq. 52: row 0 = (0, 2wz, 0) = (0, 1, 0).
    const float s = std::sqrt(0.5f);
    const float expected_z[4][4] = {{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    check_matrix(rotation_matrix(glm::quat(s, 0, 0, s)), expected_z);
}

TEST_CASE("world matrix rotates about the object's own origin, then translates (eq. 53)") {
    Pose pose;
    pose.position = {1, 2, 3};
    pose.rotation = rotation_from_axis_angle({0, 0, 1}, 90.0f);
    const glm::mat4 world = world_matrix(pose, glm::vec3(2.0f));
    // (1,0,0) scaled to (2,0,0), turned to (0,2,0), moved to (1,4,3).
    const glm::vec4 p = world * glm::vec4(1, 0, 0, 1);
    CHECK(p.x == doctest::Approx(1.0f));
    CHECK(p.y == doctest::Approx(4.0f));
    CHECK(p.z == doctest::Approx(3.0f));
    // The object's origin stays at its position whatever the rotation.
    const glm::vec4 origin = world * glm::vec4(0, 0, 0, 1);
    CHECK(origin.x == doctest::Approx(1.0f));
    CHECK(origin.y == doctest::Approx(2.0f));
    CHECK(origin.z == doctest::Approx(3.0f));
}

TEST_CASE("view matrix: Z translation is a zoom independent of rotation (eq. 54)") {
    CameraPose camera;
    camera.distance = 5.0f;
    camera.rotation = rotation_from_axis_angle({0, 1, 0}, 90.0f);
    const glm::mat4 view = view_matrix(camera);
    // The target (origin) is always straight ahead at the zoom distance.
    const glm::vec4 target = view * glm::vec4(0, 0, 0, 1);
    CHECK(target.x == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(target.z == doctest::Approx(-5.0f));
    // Turning the world 90 degrees about Y puts world +X in front (view -Z direction): x -> -z.
    const glm::vec4 x_axis = view * glm::vec4(1, 0, 0, 0);
    CHECK(x_axis.z == doctest::Approx(-1.0f));
    // By hand: view = Tz(-5)·R, so the eye is R^-1·(0,0,5) = (0,0,5) turned -90 degrees about Y = (-5,0,0).
    const glm::vec3 eye = camera_world_position(camera);
    CHECK(eye.x == doctest::Approx(-5.0f));
    CHECK(eye.y == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(eye.z == doctest::Approx(0.0f).epsilon(kTight));
    // Pan moves the target, applied before the rotation.
    camera.rotation = glm::quat(1, 0, 0, 0);
    camera.pan = {1.0f, -2.0f};
    const glm::vec4 panned = view_matrix(camera) * glm::vec4(1, -2, 0, 1);
    CHECK(panned.x == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(panned.y == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(panned.z == doctest::Approx(-5.0f));
}

TEST_CASE("euler angles compose intrinsic X then Y then Z") {
    const glm::quat q = rotation_from_euler_degrees({90, 90, 0});
    // Rx(90)·Ry(90) applied to +Z: Ry takes +Z to +X, Rx keeps +X.
    const glm::vec3 v = glm::mat3_cast(q) * glm::vec3(0, 0, 1);
    CHECK(v.x == doctest::Approx(1.0f));
    CHECK(v.y == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(v.z == doctest::Approx(0.0f).epsilon(kTight));
    CHECK(glm::length(q) == doctest::Approx(1.0f));
}

TEST_CASE("normal matrix keeps normals perpendicular under non-uniform scale") {
    Pose pose;
    const glm::mat4 world = world_matrix(pose, {2.0f, 1.0f, 1.0f});
    // Surface x = y (normal (1,-1,0)/sqrt2) becomes x = 2y; its normal must be (1,-2,0)/sqrt5.
    const glm::vec3 n = glm::normalize(normal_matrix(world) * glm::normalize(glm::vec3(1, -1, 0)));
    CHECK(n.x == doctest::Approx(1.0f / std::sqrt(5.0f)));
    CHECK(n.y == doctest::Approx(-2.0f / std::sqrt(5.0f)));
}

#include "math/arcball.hpp"

TEST_CASE("arcball: a drag to the right turns about +Y by the angle between the ball points") {
    // From the centre (0,0,1) to (0.5, 0, sqrt(0.75)): axis +Y, angle asin(0.5) = 30 degrees.
    const glm::quat q = rotation_from_axis_angle({0, 1, 0}, 30.0f);
    const glm::quat drag = arcball_rotation({0.0f, 0.0f}, {0.5f, 0.0f});
    CHECK(std::abs(std::abs(glm::dot(q, drag)) - 1.0f) < 1e-6f);
    // Upwards: about -X (the front of the ball moves up).
    const glm::vec3 front = glm::mat3_cast(arcball_rotation({0, 0}, {0, 0.5f})) * glm::vec3(0, 0, 1);
    CHECK(front.y == doctest::Approx(0.5f));
    // Outside the ball the point sits on the rim; no drag, no rotation.
    CHECK(glm::length(arcball_point({3.0f, 4.0f})) == doctest::Approx(1.0f));
    CHECK(arcball_point({3.0f, 4.0f}).z == 0.0f);
    CHECK(arcball_rotation({0.2f, 0.1f}, {0.2f, 0.1f}) == glm::quat(1, 0, 0, 0));
}

TEST_CASE("rotate_in_view turns an object the way the mouse moved, whatever the camera") {
    // The camera looks from +X (world turned -90 degrees about Y); a drag to the right must turn
    // the object about the view's up axis, world +Y.
    const glm::quat camera = rotation_from_axis_angle({0, 1, 0}, -90.0f);
    const glm::quat drag = rotation_from_axis_angle({0, 1, 0}, 30.0f);
    const glm::quat turned = rotate_in_view(glm::quat(1, 0, 0, 0), drag, camera);
    const glm::vec3 up = glm::mat3_cast(turned) * glm::vec3(0, 1, 0);
    CHECK(up.y == doctest::Approx(1.0f));
    // A view-space drag about view X maps to the world axis the camera shows as X (world +Z here).
    const glm::quat tilt = rotate_in_view(glm::quat(1, 0, 0, 0), rotation_from_axis_angle({1, 0, 0}, 90.0f), camera);
    const glm::vec3 axis = glm::axis(tilt);
    CHECK(std::abs(axis.z) == doctest::Approx(1.0f));
}
