// boreas: the camera, shared by every vertex shader of the frame. In the shadow pass
// (BOREAS_SHADOW_PASS) u_view_proj is the sun's projection and the fragment shaders only
// keep depth (and the leaves' alpha test).
uniform mat4 u_view_proj;  // world -> clip
