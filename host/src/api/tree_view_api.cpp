// boreas: a view for boreas_world_enqueue_tree_records from a camera (boreas_set_tree_view_
// camera, boreas_cl.h): the six planes of its perspective frustum, its eye and the angle a
// pixel spans, in double from the camera's pose and projection as an engine keeps them.
#include <array>
#include <cmath>
#include <string>

#include "api/c_api_guard.h"
#include "boreas/boreas_cl.h"
#include "errors.h"
#include "validation.h"

namespace {

using Vec = std::array<double, 3>;
constexpr double kPi = 3.14159265358979323846;

Vec vec(const float v[3]) { return {double(v[0]), double(v[1]), double(v[2])}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec add(const Vec& a, const Vec& b, double k) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]}; }

// A direction (forward, up) checked finite and of non-zero length, made unit.
Vec unit_direction(const float* v, const char* what) {
  if (!v) boreas::impl::fail_argument(std::string(what) + " is NULL");
  for (int a = 0; a < 3; ++a) boreas::impl::check_finite(v[a], std::string(what) + "[" + std::to_string(a) + "]");
  const Vec d = vec(v);
  const double length = std::sqrt(dot(d, d));
  if (!(length > 0.0)) boreas::impl::fail_argument(std::string(what) + " has zero length");
  return {d[0] / length, d[1] / length, d[2] / length};
}

// Plane k of the view: inside where n . p + d >= 0, n made unit, through `at`.
void set_plane(boreas_tree_view_def* view, int k, const Vec& n, const Vec& at, double offset = 0.0) {
  const double length = std::sqrt(dot(n, n));
  for (int a = 0; a < 3; ++a) view->planes[k][a] = float(n[size_t(a)] / length);
  view->planes[k][3] = float((-dot(n, at) + offset) / length);
}

}  // namespace

boreas_status boreas_set_tree_view_camera(boreas_tree_view_def* view, const float eye[3],
                                          const float forward[3], const float up[3],
                                          float vertical_fov, float aspect, float near_m,
                                          float far_m, int viewport_height) {
  return boreas::api::guarded(__func__, [&] {
    using boreas::impl::fail_argument;
    using boreas::impl::num;
    if (!view) fail_argument("view is NULL");
    boreas::impl::check_position(eye, "eye");
    const Vec f = unit_direction(forward, "forward"), u0 = unit_direction(up, "up");
    const Vec r0 = cross(f, u0);
    // Within about 0.06 degrees of forward the right axis is mostly rounding.
    if (std::sqrt(dot(r0, r0)) < 1e-3) fail_argument("up is parallel to forward");
    boreas::impl::check_finite(vertical_fov, "vertical_fov");
    if (!(vertical_fov > 0.0f && double(vertical_fov) < kPi))
      fail_argument("vertical_fov must be in (0, pi) rad (got " + num(vertical_fov) + ")");
    boreas::impl::check_finite(aspect, "aspect");
    if (!(aspect > 0.0f)) fail_argument("aspect must be > 0 (got " + num(aspect) + ")");
    boreas::impl::check_finite(near_m, "near_m");
    boreas::impl::check_finite(far_m, "far_m");
    if (!(near_m > 0.0f)) fail_argument("near_m must be > 0 (got " + num(near_m) + ")");
    if (!(far_m > near_m))
      fail_argument("far_m must be > near_m (got " + num(far_m) + " and " + num(near_m) + ")");
    if (viewport_height < 1)
      fail_argument("viewport_height must be >= 1 pixel (got " + std::to_string(viewport_height) + ")");
    const double len = std::sqrt(dot(r0, r0));
    const Vec r = {r0[0] / len, r0[1] / len, r0[2] / len}, u = cross(r, f);
    // A point eye + x r + y u + z f is inside where |x| <= z tx, |y| <= z ty and
    // near <= z <= far: the planes of a GL perspective projection (left, right, bottom,
    // top, near, far, the order of a view-projection matrix's rows).
    const double ty = std::tan(0.5 * double(vertical_fov)), tx = ty * double(aspect);
    // The angle a pixel spans at the image's centre (rad); checked before the view is
    // written, so a refused call leaves it as it was.
    const double pixel = 2.0 * ty / double(viewport_height);
    if (!(pixel < 1.0))
      fail_argument("a pixel would span " + num(pixel) + " rad, >= 1 (vertical_fov " + num(vertical_fov) +
                    " over viewport_height " + std::to_string(viewport_height) + ")");
    const Vec e = vec(eye);
    set_plane(view, 0, add(r, f, tx), e);
    set_plane(view, 1, add({-r[0], -r[1], -r[2]}, f, tx), e);
    set_plane(view, 2, add(u, f, ty), e);
    set_plane(view, 3, add({-u[0], -u[1], -u[2]}, f, ty), e);
    set_plane(view, 4, f, e, -double(near_m));
    set_plane(view, 5, {-f[0], -f[1], -f[2]}, e, double(far_m));
    for (int a = 0; a < 3; ++a) view->eye[a] = eye[a];
    view->pixel_angle = float(pixel);
  });
}
