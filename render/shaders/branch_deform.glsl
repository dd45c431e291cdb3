// boreas: the branch deformer of Skjermo (2007) sec. 3 in GLSL, the same math as
// cl/shared/tree_math.h (boreas_sloan_frame, boreas_frame_handles, boreas_branch_radius,
// boreas_branch_surface) with GLSL's builtins in place of boreas's fast math. Keep the
// two in step: tests/render/gl compares this shader's vertices with the OpenCL
// deformer's (boreas_tree_get_mesh).
//
// Branch records come from boreas_tree_enqueue_branch_records (boreas_cl.h): 28 floats,
// P0..P3, O, then radius, taper depth, taper exponent, flare, bulge count, bulge depth,
// lobe count, lobe depth, lobe taper, the broken flag (unread here), the tip's cap, the
// beads' phase and a zero.

layout(std430, binding = 0) readonly buffer BranchRecords { float branch_record[]; };

struct Branch {
  vec3 p0, p1, p2, p3, o;
  float radius, taper_depth, taper_exponent, flare, bulge_count, bulge_depth, lobe_count, lobe_depth, lobe_taper;
  float tip_cap, bulge_phase;
};

vec3 record_vec3(int base, int at) {
  return vec3(branch_record[base + at], branch_record[base + at + 1], branch_record[base + at + 2]);
}

Branch load_branch(int index) {
  int b = index * 28;
  Branch r;
  r.p0 = record_vec3(b, 0);
  r.p1 = record_vec3(b, 3);
  r.p2 = record_vec3(b, 6);
  r.p3 = record_vec3(b, 9);
  r.o = record_vec3(b, 12);
  r.radius = branch_record[b + 15];
  r.taper_depth = branch_record[b + 16];
  r.taper_exponent = branch_record[b + 17];
  r.flare = branch_record[b + 18];
  r.bulge_count = branch_record[b + 19];
  r.bulge_depth = branch_record[b + 20];
  r.lobe_count = branch_record[b + 21];
  r.lobe_depth = branch_record[b + 22];
  r.lobe_taper = branch_record[b + 23];
  r.tip_cap = branch_record[b + 25];
  r.bulge_phase = branch_record[b + 26];
  return r;
}

vec3 bezier_point(Branch c, float u) {
  float w = 1.0 - u;
  return w * w * w * c.p0 + 3.0 * u * w * w * c.p1 + 3.0 * u * u * w * c.p2 + u * u * u * c.p3;
}

vec3 bezier_derivative(Branch c, float u) {
  float w = 1.0 - u;
  return 3.0 * w * w * (c.p1 - c.p0) + 6.0 * u * w * (c.p2 - c.p1) + 3.0 * u * u * (c.p3 - c.p2);
}

// The Sloan frame's handles (eq. 8): s[k], t[k] for the three control polygon legs.
void sloan_frame(Branch c, out vec3 s[3], out vec3 t[3]) {
  vec3 l0 = normalize(c.p1 - c.p0), l1 = normalize(c.p2 - c.p1), l2 = normalize(c.p3 - c.p2);
  s[0] = normalize(cross(l0, c.o));
  t[0] = cross(s[0], l0);
  t[1] = normalize(cross(s[0], l1));
  s[1] = cross(l1, t[1]);
  t[2] = normalize(cross(s[1], l2));
  s[2] = cross(l2, t[2]);
}

const float kTwoPi = 6.28318530717958647;

// Where mesh ring `ring` of `rings` sits along v (boreas_ring_v, BOREAS_CAP_RINGS): evenly,
// but round the tip's cap where a piece has one (0 < cap < 1/2).
float ring_v(int ring, int rings, float cap) {
  float even = float(ring) / float(rings);
  int m = rings < 2 ? 0 : clamp((rings + 2) / 4, 1, 3);
  if (m == 0 || !(cap > 0.0 && cap < 0.5)) return even;
  float body = float(rings - m);
  if (float(ring) <= body) return float(ring) / body * (1.0 - cap);
  float half_angle = sin(kTwoPi * float(rings - ring) / (8.0 * float(m)));
  return 1.0 - 2.0 * cap * half_angle * half_angle;
}

// Surface point and unit outward normal at (v, theta in turns): eq. 2-9 and sec. 3.4.
void branch_surface(Branch c, float v, float turns, out vec3 position, out vec3 normal) {
  vec3 fs[3], ft[3];
  sloan_frame(c, fs, ft);
  float w = 1.0 - v;
  vec3 s = fs[0] * (w * w) + fs[1] * (2.0 * v * w) + fs[2] * (v * v);
  vec3 t = ft[0] * (w * w) + ft[1] * (2.0 * v * w) + ft[2] * (v * v);
  vec3 ds = (fs[1] - fs[0]) * (2.0 * w) + (fs[2] - fs[1]) * (2.0 * v);
  vec3 dt = (ft[1] - ft[0]) * (2.0 * w) + (ft[2] - ft[1]) * (2.0 * v);

  // Radius functions (eq. 2-5) and their derivatives, as boreas_branch_radius.
  // GLSL leaves pow(0, y <= 0) undefined (llvmpipe gives 0): v^0 is 1 here, as in C.
  float vt1 = c.taper_exponent > 1.0 ? pow(v, c.taper_exponent - 1.0) : 1.0;
  float taper = 1.0 - c.taper_depth * vt1 * v;
  float d_taper = -c.taper_depth * c.taper_exponent * vt1;
  float e = max(1.0 - 8.0 * v, 0.0);
  float p100 = exp2(e * 6.64385618977472470);
  float flare = 1.0 + c.flare * (p100 - 1.0) * 0.01;
  float d_flare = (e > 0.0 ? 1.0 : 0.0) * c.flare * 0.01 * p100 * 4.60517018598809136 * -8.0;
  // Bulges as Arbaro's beads (boreas_beads): z radii from the nearest waist, x from the tip.
  float bead_x = 2.0 * (c.bulge_count * (1.0 - v) + c.bulge_phase);
  float bead_xo = max(bead_x, 1.0);
  float bead_y = bead_xo - 2.0 * floor(0.5 * bead_xo + 0.5);
  float bead_z = abs(bead_y);
  float bead_root = sqrt(bead_z * (2.0 - bead_z));
  float bulges = 1.0 - c.bulge_depth + c.bulge_depth * bead_root;
  float bead_dz = (bead_y > 0.0 ? -2.0 : 2.0) * c.bulge_count;
  float bead_held = max(bead_root, 0.05);  // BOREAS_BEAD_CREASE
  float bead_slope = c.bulge_depth * (1.0 - bead_z) * bead_root / (bead_held * bead_held) * bead_dz;
  float d_bulges = bead_x > 1.0 ? bead_slope : 0.0;
  float lobe_angle = kTwoPi * c.lobe_count * turns;
  float lobe_fade = 1.0 - v * c.lobe_taper;
  float lobes = 1.0 + c.lobe_depth * sin(lobe_angle) * lobe_fade;
  float d_lobes_dv = -c.lobe_depth * sin(lobe_angle) * c.lobe_taper;
  // The tip's hemisphere (boreas_tip_cap): sqrt(w (2 - w)) over the last tip_cap of v.
  float cap_w = c.tip_cap > 0.0 ? clamp((1.0 - v) / c.tip_cap, 0.0, 1.0) : 1.0;
  float cap = sqrt(cap_w * (2.0 - cap_w));
  float d_cap = cap_w < 1.0 ? -(1.0 - cap_w) / (c.tip_cap * max(cap, 1e-3)) : 0.0;
  float radial = taper * flare * bulges;
  float open = c.radius * radial * lobes;
  float d_open = c.radius * ((d_taper * flare * bulges + taper * d_flare * bulges + taper * flare * d_bulges) * lobes +
                             radial * d_lobes_dv);
  float r = open * cap;
  float dr_dv = d_open * cap + open * d_cap;
  float d_lobes = c.lobe_depth * c.lobe_count * cos(lobe_angle) * lobe_fade;

  float sin_t = sin(kTwoPi * turns), cos_t = cos(kTwoPi * turns);
  vec3 dir = s * sin_t + t * cos_t;
  vec3 ddir_dv = ds * sin_t + dt * cos_t;
  vec3 ddir_dtheta = s * cos_t - t * sin_t;
  position = bezier_point(c, v) + dir * r;
  vec3 x_v = bezier_derivative(c, v) + dir * dr_dv + ddir_dv * r;
  vec3 x_theta = dir * d_lobes + ddir_dtheta * lobes;
  normal = normalize(cross(x_theta, x_v));
}
