// boreas sky: direct sunlight at the ground under a clear sky, after Preetham, Shirley and
// Smits (1999), appendix A.1: the extraterrestrial solar spectrum times the transmittance of
// Rayleigh scattering, aerosols (Angstrom's law), ozone, mixed gases and water vapour,
// integrated over 380-780 nm against the CIE 1931 color matching functions.
//
// Sources of the numbers:
//   - transmittance formulas and constants: Preetham et al. 1999, appendix A.1, which takes
//     them from Iqbal, "An Introduction to Solar Radiation" (1983): relative optical mass
//     (Kasten), Rayleigh 0.008735 lambda^-4.08, aerosol beta = 0.04608 T - 0.04586 with
//     alpha = 1.3, ozone column l = 0.35 cm, precipitable water w = 2 cm;
//   - absorption coefficient tables k_o, k_g, k_wa (1/cm): Iqbal pp. 127-130, as published
//     with the paper's sample code;
//   - extraterrestrial solar spectral radiance, 380-750 nm every 10 nm, W/(m^2 sr nm): the
//     table published with the paper's sample code; held at its 750 nm value up to 780 nm
//     (the color matching functions are below 0.1 % of their peak there);
//   - color matching functions: the multi-lobe Gaussian fit of Wyman, Sloan and Shirley,
//     "Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2013,
//     a close fit to the tabulated CIE 1931 2-degree observer that needs no table.
#pragma once

#include <glm/vec3.hpp>

namespace boreas::render {

// The sun's angular radius seen from the Earth at 1 AU: asin(695,700 km / 149,597,870.7 km),
// radians (0.26645 degrees).
inline constexpr double kSunAngularRadiusRad = 4.65048402361498e-3;

// Solid angle of the sun's disc, sr (about 6.794e-5).
double sun_solid_angle_sr();

// Relative optical air mass toward a sun at zenith angle sun_zenith_rad in [0, pi/2]: 1 at the
// zenith, about 36.5 at the horizon (Kasten's formula, as in Preetham's appendix A.1).
double relative_air_mass(double sun_zenith_rad);

// Absorption coefficients (k_o, k_g, k_wa) of ozone, mixed gases and water vapour at
// wavelength_nm, 1/cm: Iqbal's tables, interpolated linearly.
glm::dvec3 atmosphere_absorption_per_cm(double wavelength_nm);

// Fraction of direct sunlight of wavelength wavelength_nm that crosses the atmosphere toward a
// sun at zenith angle sun_zenith_rad in [0, pi/2], for turbidity in [1.7, 10].
double sun_transmittance(double wavelength_nm, double turbidity, double sun_zenith_rad);

// Extraterrestrial solar spectral radiance, W/(m^2 sr nm).
double solar_spectral_radiance(double wavelength_nm);

// CIE 1931 2-degree color matching functions (x_bar, y_bar, z_bar) at wavelength_nm.
glm::dvec3 cie_1931_color_matching(double wavelength_nm);

// CIE XYZ of the direct normal illuminance of sunlight at the ground, in klx (Y is the
// illuminance itself: about 100 klx with a clear sky and the sun at the zenith).
glm::dvec3 sunlight_xyz_klx(double turbidity, double sun_zenith_rad);

}  // namespace boreas::render
