// boreas views: `boreas run --window`'s input, gathered from the window system's callbacks
// between frames and turned into motion by elapsed time, so a slow frame (llvmpipe draws a
// forest at well under a frame a second) neither loses a tap or a drag nor slows the
// camera down. Plain functions of events and times: no window is needed to test them.
#pragma once

#include <array>

#include "gl/camera.h"

namespace boreas::render {

// The keys the window reacts to, whatever the window system calls them.
enum class WindowKey : int {
  left, right, up, down,  // orbit: yaw and pitch
  zoom_in, zoom_out,      // + and -
  wind_up, wind_down,     // W, S: stronger, weaker
  wind_left, wind_right,  // A, D: turn the waves
  count
};

// What happened between two frames: for each key the seconds it was held (a press and
// release inside one batch of events counts as kTapSeconds), the mouse's drag (pixels moved
// with the left button down) and the wheel's notches.
struct FrameInput {
  std::array<double, size_t(WindowKey::count)> held_s{};
  double drag_x = 0.0, drag_y = 0.0;  // pixels, +x right, +y down
  double scroll = 0.0;                // notches, + away from the user
  double seconds(WindowKey key) const { return held_s[size_t(key)]; }
};

// Events arrive with the time (s, any steady clock) they were seen; take() closes the
// interval at `now` and starts the next one.
class InputAccumulator {
 public:
  // Window systems deliver a frame's events together, when they are polled: a key pressed
  // and released in one poll had some unknown short press. It counts as this long.
  static constexpr double kTapSeconds = 0.1;

  void key(WindowKey key, bool down, double time_s);
  void mouse_button(bool down, double x, double y);
  void cursor(double x, double y);
  void scroll(double notches);
  FrameInput take(double now_s);

 private:
  struct KeyState {
    bool down = false;
    double since_s = 0.0;  // the press, or the last take() while held
    double held_s = 0.0;   // held so far in this interval
  };
  std::array<KeyState, size_t(WindowKey::count)> keys_{};
  bool dragging_ = false;
  double last_x_ = 0.0, last_y_ = 0.0;
  FrameInput pending_;
};

// How fast held keys move things, per second of holding.
struct WindowRates {
  float turn_deg_per_s = 60.0f;    // left, right
  float pitch_deg_per_s = 40.0f;   // up, down
  float zoom_per_s = 2.0f;         // + and -: the distance shrinks or grows by this factor
  float zoom_per_notch = 1.1f;     // the wheel: factor per notch
  float drag_deg_per_pixel = 0.3f;
  float wind_scale_per_s = 2.0f;   // W, S: factor
  float wind_turn_deg_per_s = 45.0f;
};

// What the keys and the mouse change: the orbit and the wind.
struct WindowControls {
  Orbit orbit;
  float wind_scale = 1.0f;     // multiplies the scene's wave amplitudes, 0..kMaxWindScale
  float wind_turn_deg = 0.0f;  // turns the waves' directions about +Y
  bool wind_changed = false;   // set when the wind moved; the caller clears it
  static constexpr float kMaxWindScale = 10.0f;
};

// Moves the controls by one frame's input.
void apply_input(const FrameInput& input, const WindowRates& rates, WindowControls& controls);

}  // namespace boreas::render
