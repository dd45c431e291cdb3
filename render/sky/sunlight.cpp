// boreas sky: direct sunlight after the clear atmosphere (Preetham et al. 1999, appendix A.1);
// the tables and their sources are listed in sunlight.h.
#include "sky/sunlight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Lumens per watt at 555 nm: turns the y_bar integral of a radiometric spectrum into
// photometric units.
constexpr double kMaxLuminousEfficacy = 683.0;

// The spectral integral runs over 380-780 nm in steps of 5 nm (trapezoid rule): fine enough
// for the 10 nm tables and the narrow oxygen band at 760 nm.
constexpr double kFirstNm = 380.0;
constexpr double kLastNm = 780.0;
constexpr double kStepNm = 5.0;

// Atmosphere of appendix A.1: Angstrom's wavelength exponent for aerosols, the ozone column
// (cm at NTP) and precipitable water vapour (cm).
constexpr double kAngstromAlpha = 1.3;
constexpr double kOzoneColumnCm = 0.35;
constexpr double kWaterVapourCm = 2.0;

struct SpectrumPoint {
  double nm;
  double value;
};

// Ozone absorption coefficient k_o, 1/cm (Iqbal p. 127). The Huggins band below 355 nm lies
// outside the visible integral and is left out; 355 nm anchors the interpolation to 445 nm.
constexpr std::array<SpectrumPoint, 53> kOzoneAbsorption = {{
    {355, 0.0},   {445, 0.003}, {450, 0.003}, {455, 0.004}, {460, 0.006}, {465, 0.008},
    {470, 0.009}, {475, 0.012}, {480, 0.014}, {485, 0.017}, {490, 0.021}, {495, 0.025},
    {500, 0.03},  {505, 0.035}, {510, 0.04},  {515, 0.045}, {520, 0.048}, {525, 0.057},
    {530, 0.063}, {535, 0.07},  {540, 0.075}, {545, 0.08},  {550, 0.085}, {555, 0.095},
    {560, 0.103}, {565, 0.110}, {570, 0.12},  {575, 0.122}, {580, 0.12},  {585, 0.118},
    {590, 0.115}, {595, 0.12},  {600, 0.125}, {605, 0.130}, {610, 0.12},  {620, 0.105},
    {630, 0.09},  {640, 0.079}, {650, 0.067}, {660, 0.057}, {670, 0.048}, {680, 0.036},
    {690, 0.028}, {700, 0.023}, {710, 0.018}, {720, 0.014}, {730, 0.011}, {740, 0.010},
    {750, 0.009}, {760, 0.007}, {770, 0.004}, {780, 0.0},   {790, 0.0},
}};

// Mixed gases (the oxygen A band) k_g, 1/cm (Iqbal p. 130).
constexpr std::array<SpectrumPoint, 4> kGasAbsorption = {{
    {759, 0.0},
    {760, 3.0},
    {770, 0.210},
    {771, 0.0},
}};

// Water vapour k_wa, 1/cm (Iqbal p. 130).
constexpr std::array<SpectrumPoint, 13> kWaterAbsorption = {{
    {689, 0.0},
    {690, 0.016},
    {700, 0.024},
    {710, 0.0125},
    {720, 1.0},
    {730, 0.87},
    {740, 0.061},
    {750, 0.001},
    {760, 0.00001},
    {770, 0.00001},
    {780, 0.0006},
    {790, 0.0175},
    {800, 0.036},
}};

// Extraterrestrial solar spectral radiance, W/(m^2 sr nm), 380 to 750 nm every 10 nm.
constexpr double kSolarFirstNm = 380.0;
constexpr double kSolarStepNm = 10.0;
constexpr std::array<double, 38> kSolarRadiance = {
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2,
};

// Linear interpolation in a table sorted by wavelength; the end values hold outside it.
template <std::size_t N>
double interpolate(const std::array<SpectrumPoint, N>& table, double nm) {
  if (nm <= table.front().nm) return table.front().value;
  if (nm >= table.back().nm) return table.back().value;
  auto upper = std::upper_bound(table.begin(), table.end(), nm,
                                [](double v, const SpectrumPoint& p) { return v < p.nm; });
  auto lower = upper - 1;
  double t = (nm - lower->nm) / (upper->nm - lower->nm);
  return lower->value + t * (upper->value - lower->value);
}

// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with a different width on either side
// of its peak (nm).
double lobe(double nm, double peak_nm, double sigma_below_nm, double sigma_above_nm) {
  double t = (nm - peak_nm) / (nm < peak_nm ? sigma_below_nm : sigma_above_nm);
  return std::exp(-0.5 * t * t);
}

}  // namespace

double sun_solid_angle_sr() { return 2.0 * kPi * (1.0 - std::cos(kSunAngularRadiusRad)); }

double relative_air_mass(double sun_zenith_rad) {
  double zenith_deg = sun_zenith_rad * 180.0 / kPi;
  return 1.0 / (std::cos(sun_zenith_rad) + 0.15 * std::pow(93.885 - zenith_deg, -1.253));
}

glm::dvec3 atmosphere_absorption_per_cm(double wavelength_nm) {
  return {interpolate(kOzoneAbsorption, wavelength_nm), interpolate(kGasAbsorption, wavelength_nm),
          interpolate(kWaterAbsorption, wavelength_nm)};
}

double sun_transmittance(double wavelength_nm, double turbidity, double sun_zenith_rad) {
  const glm::dvec3 k = atmosphere_absorption_per_cm(wavelength_nm);
  const double m = relative_air_mass(sun_zenith_rad);
  const double um = wavelength_nm / 1000.0;  // the fits take micrometres
  const double rayleigh = std::exp(-0.008735 * std::pow(um, -4.08) * m);
  const double beta = 0.04608 * turbidity - 0.04586;  // Angstrom's turbidity coefficient
  const double aerosol = std::exp(-beta * std::pow(um, -kAngstromAlpha) * m);
  const double ozone = std::exp(-k.x * kOzoneColumnCm * m);
  const double gas = std::exp(-1.41 * k.y * m / std::pow(1.0 + 118.93 * k.y * m, 0.45));
  const double k_wa_w_m = k.z * kWaterVapourCm * m;
  const double water = std::exp(-0.2385 * k_wa_w_m / std::pow(1.0 + 20.07 * k_wa_w_m, 0.45));
  return rayleigh * aerosol * ozone * gas * water;
}

double solar_spectral_radiance(double wavelength_nm) {
  double position = (wavelength_nm - kSolarFirstNm) / kSolarStepNm;
  const double last = double(kSolarRadiance.size() - 1);
  if (position <= 0.0) return kSolarRadiance.front();
  if (position >= last) return kSolarRadiance.back();
  const auto i = std::size_t(position);
  const double t = position - double(i);
  return kSolarRadiance[i] + t * (kSolarRadiance[i + 1] - kSolarRadiance[i]);
}

glm::dvec3 cie_1931_color_matching(double nm) {
  return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
              0.065 * lobe(nm, 501.1, 20.4, 26.2),
          0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
          1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

glm::dvec3 sunlight_xyz_klx(double turbidity, double sun_zenith_rad) {
  // Radiance integral in W/(m^2 sr), weighted by the color matching functions.
  glm::dvec3 sum(0.0);
  const int steps = int(std::lround((kLastNm - kFirstNm) / kStepNm));
  for (int i = 0; i <= steps; ++i) {
    const double nm = kFirstNm + kStepNm * i;
    const double weight = (i == 0 || i == steps) ? 0.5 * kStepNm : kStepNm;
    const double radiance =
        solar_spectral_radiance(nm) * sun_transmittance(nm, turbidity, sun_zenith_rad);
    sum += weight * radiance * cie_1931_color_matching(nm);
  }
  // The sun is small enough that its irradiance is radiance times solid angle; lx -> klx.
  return sum * (kMaxLuminousEfficacy * sun_solid_angle_sr() / 1000.0);
}

}  // namespace boreas::render
