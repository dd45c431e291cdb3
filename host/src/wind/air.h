// boreas: the air every plant's drag is computed with, so that one gust loads trees, blades
// and their leaves alike (1/2 rho C_d A |u| u), and the gravity their weight takes.
#pragma once

namespace boreas::impl {

inline constexpr double kAirDensity = 1.2;  // kg/m^3: dry air at sea level and 20 C
inline constexpr double kGravity = 9.80665;  // m/s^2, along -y

}  // namespace boreas::impl
