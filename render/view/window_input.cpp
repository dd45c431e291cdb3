// boreas views: window input accumulated between frames (window_input.h).
#include "view/window_input.h"

#include <algorithm>
#include <cmath>

namespace boreas::render {

void InputAccumulator::key(WindowKey key, bool down, double time_s) {
  KeyState& k = keys_[size_t(key)];
  if (down == k.down) return;  // a repeat
  if (down) {
    k.since_s = time_s;
  } else {
    // At least a tap: a press and release seen in one poll share a time.
    k.held_s += std::max(time_s - k.since_s, kTapSeconds);
  }
  k.down = down;
}

void InputAccumulator::mouse_button(bool down, double x, double y) {
  if (dragging_) cursor(x, y);  // the last stretch before the release
  dragging_ = down;
  last_x_ = x;
  last_y_ = y;
}

void InputAccumulator::cursor(double x, double y) {
  if (dragging_) {
    pending_.drag_x += x - last_x_;
    pending_.drag_y += y - last_y_;
  }
  last_x_ = x;
  last_y_ = y;
}

void InputAccumulator::scroll(double notches) { pending_.scroll += notches; }

FrameInput InputAccumulator::take(double now_s) {
  FrameInput out = pending_;
  for (size_t i = 0; i < keys_.size(); ++i) {
    KeyState& k = keys_[i];
    double held = k.held_s;
    if (k.down) {
      held += std::max(now_s - k.since_s, 0.0);
      k.since_s = now_s;
    }
    out.held_s[i] = held;
    k.held_s = 0.0;
  }
  pending_ = FrameInput{};
  return out;
}

void apply_input(const FrameInput& in, const WindowRates& r, WindowControls& c) {
  auto net = [&](WindowKey plus, WindowKey minus) { return float(in.seconds(plus) - in.seconds(minus)); };
  c.orbit.turn(r.turn_deg_per_s * net(WindowKey::right, WindowKey::left) +
                   r.drag_deg_per_pixel * float(in.drag_x),
               r.pitch_deg_per_s * net(WindowKey::up, WindowKey::down) +
                   r.drag_deg_per_pixel * float(in.drag_y));
  // Zooming in shrinks the distance: + and a wheel turned away from the user.
  const float zoom_s = net(WindowKey::zoom_out, WindowKey::zoom_in);
  c.orbit.zoom(std::pow(r.zoom_per_s, zoom_s) * std::pow(r.zoom_per_notch, -float(in.scroll)));
  const float scale_s = net(WindowKey::wind_up, WindowKey::wind_down);
  const float turn_s = net(WindowKey::wind_right, WindowKey::wind_left);
  if (scale_s != 0.0f || turn_s != 0.0f) {
    c.wind_scale = std::clamp(c.wind_scale * std::pow(r.wind_scale_per_s, scale_s), 0.0f,
                              WindowControls::kMaxWindScale);
    c.wind_turn_deg += r.wind_turn_deg_per_s * turn_s;
    c.wind_changed = true;
  }
}

}  // namespace boreas::render
