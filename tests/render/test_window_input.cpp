// `boreas run --window`'s input (render/view/window_input.h): events gathered between
// frames, motion by elapsed time rather than by frame.
#include <gtest/gtest.h>

#include <cmath>

#include "view/window_input.h"

namespace boreas::render {
namespace {

TEST(WindowInput, AKeyHeldAcrossFramesCountsTheTimeItWasHeldInEach) {
  InputAccumulator input;
  input.key(WindowKey::left, true, 10.0);
  EXPECT_DOUBLE_EQ(input.take(10.5).seconds(WindowKey::left), 0.5);
  EXPECT_DOUBLE_EQ(input.take(13.0).seconds(WindowKey::left), 2.5);
  input.key(WindowKey::left, false, 13.25);
  EXPECT_DOUBLE_EQ(input.take(14.0).seconds(WindowKey::left), 0.25);
  EXPECT_DOUBLE_EQ(input.take(20.0).seconds(WindowKey::left), 0.0);
}

TEST(WindowInput, ATapBetweenTwoFramesIsNotLost) {
  // Both events of a tap arrive in one poll, with one time.
  InputAccumulator input;
  input.key(WindowKey::wind_up, true, 3.0);
  input.key(WindowKey::wind_up, false, 3.0);
  FrameInput frame = input.take(7.0);
  EXPECT_DOUBLE_EQ(frame.seconds(WindowKey::wind_up), InputAccumulator::kTapSeconds);
  EXPECT_DOUBLE_EQ(frame.seconds(WindowKey::wind_down), 0.0);
  // Two taps in one frame count twice; repeats of a held key count once.
  input.key(WindowKey::right, true, 8.0);
  input.key(WindowKey::right, false, 8.0);
  input.key(WindowKey::right, true, 8.0);
  input.key(WindowKey::right, true, 8.0);
  input.key(WindowKey::right, false, 8.5);
  EXPECT_DOUBLE_EQ(input.take(9.0).seconds(WindowKey::right), InputAccumulator::kTapSeconds + 0.5);
}

TEST(WindowInput, AQuickDragBetweenFramesIsSummedAndOnlyWithTheButtonDown) {
  InputAccumulator input;
  input.cursor(100.0, 100.0);  // moving without the button: no drag
  input.mouse_button(true, 110.0, 100.0);
  input.cursor(130.0, 90.0);
  input.cursor(150.0, 80.0);
  input.mouse_button(false, 155.0, 85.0);
  input.cursor(400.0, 400.0);
  input.scroll(1.0);
  input.scroll(2.0);
  FrameInput frame = input.take(1.0);
  EXPECT_DOUBLE_EQ(frame.drag_x, 45.0);
  EXPECT_DOUBLE_EQ(frame.drag_y, -15.0);
  EXPECT_DOUBLE_EQ(frame.scroll, 3.0);
  FrameInput next = input.take(2.0);
  EXPECT_DOUBLE_EQ(next.drag_x, 0.0);
  EXPECT_DOUBLE_EQ(next.scroll, 0.0);
}

// Holding a key for the same wall time turns the camera by the same angle, however many
// frames the time is cut into.
TEST(WindowInput, TheCameraTurnsByTimeNotByFrame) {
  auto turned_after = [](int frames, double seconds) {
    InputAccumulator input;
    WindowControls controls;
    controls.orbit.yaw_deg = 0.0f;
    input.key(WindowKey::left, true, 0.0);
    for (int i = 1; i <= frames; ++i)
      apply_input(input.take(seconds * i / frames), WindowRates{}, controls);
    return controls.orbit.yaw_deg;
  };
  const WindowRates rates;
  // Left turns toward -yaw at the rate for 5 s: -300 degrees, seen modulo 360.
  const float expected = std::fmod(-rates.turn_deg_per_s * 5.0f, 360.0f);
  EXPECT_NEAR(turned_after(1, 5.0), expected, 1e-3);  // one slow frame
  EXPECT_NEAR(turned_after(300, 5.0), expected, 1e-2);  // 60 Hz
}

TEST(WindowInput, ZoomAndWindFollowTheirRatesAndLimits) {
  WindowControls controls;
  controls.orbit.distance = 100.0f;
  WindowRates rates;
  FrameInput in;
  in.held_s[size_t(WindowKey::zoom_in)] = 1.0;
  in.held_s[size_t(WindowKey::wind_up)] = 2.0;
  apply_input(in, rates, controls);
  EXPECT_NEAR(controls.orbit.distance, 100.0f / rates.zoom_per_s, 1e-3);
  EXPECT_NEAR(controls.wind_scale, rates.wind_scale_per_s * rates.wind_scale_per_s, 1e-5);
  EXPECT_TRUE(controls.wind_changed);

  FrameInput wheel;
  wheel.scroll = 2.0;  // two notches away from the user: closer
  apply_input(wheel, rates, controls);
  EXPECT_NEAR(controls.orbit.distance, 50.0f / (rates.zoom_per_notch * rates.zoom_per_notch), 1e-3);

  FrameInput long_push;
  long_push.held_s[size_t(WindowKey::wind_up)] = 60.0;
  long_push.held_s[size_t(WindowKey::wind_right)] = 2.0;
  apply_input(long_push, rates, controls);
  EXPECT_FLOAT_EQ(controls.wind_scale, WindowControls::kMaxWindScale);
  EXPECT_NEAR(controls.wind_turn_deg, 2.0f * rates.wind_turn_deg_per_s, 1e-4);

  // Nothing pressed: nothing moves and the wind is left alone.
  WindowControls still;
  still.orbit.distance = 10.0f;
  apply_input(FrameInput{}, rates, still);
  EXPECT_FLOAT_EQ(still.orbit.distance, 10.0f);
  EXPECT_FALSE(still.wind_changed);
}

}  // namespace
}  // namespace boreas::render
