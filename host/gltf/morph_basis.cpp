// boreas gltf: a mesh's motion as a few morph targets (morph_basis.h).
#include "morph_basis.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace boreas::gltf {
namespace {

using Keys = std::vector<std::vector<float>>;

// The largest distance of any vertex at any key from where it belongs.
double largest_distance(const Keys& residual) {
  double most = 0.0;
  for (const std::vector<float>& r : residual)
    for (size_t v = 0; v + 2 < r.size(); v += 3)
      most = std::max(most, double(r[v]) * r[v] + double(r[v + 1]) * r[v + 1] + double(r[v + 2]) * r[v + 2]);
  return std::sqrt(most);
}

std::vector<double> gram(const Keys& residual) {
  const size_t n = residual.size();
  std::vector<double> g(n * n, 0.0);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a; b < n; ++b) {
      double s = 0.0;
      for (size_t i = 0; i < residual[a].size(); ++i) s += double(residual[a][i]) * residual[b][i];
      g[a * n + b] = g[b * n + a] = s;
    }
  return g;
}

// Rotates rows/columns p and q of a (n x n) and the columns of v to zero a[p][q].
void jacobi_rotate(std::vector<double>& a, std::vector<double>& v, size_t n, size_t p, size_t q) {
  const double apq = a[p * n + q];
  const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
  const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
  const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
  for (size_t k = 0; k < n; ++k) {  // columns p, q
    const double akp = a[k * n + p], akq = a[k * n + q];
    a[k * n + p] = c * akp - s * akq;
    a[k * n + q] = s * akp + c * akq;
  }
  for (size_t k = 0; k < n; ++k) {  // rows p, q
    const double apk = a[p * n + k], aqk = a[q * n + k];
    a[p * n + k] = c * apk - s * aqk;
    a[q * n + k] = s * apk + c * aqk;
  }
  for (size_t k = 0; k < n; ++k) {
    const double vkp = v[k * n + p], vkq = v[k * n + q];
    v[k * n + p] = c * vkp - s * vkq;
    v[k * n + q] = s * vkp + c * vkq;
  }
}

// The target along direction b (the part's displacement field): quantized, its weights
// fitted to the residual by least squares and taken off it. False if b is nil.
bool add_target(const std::vector<double>& b, const std::array<double, 3>& extent, double tolerance,
                Keys* residual, MorphTargets* out) {
  double scale = 0.0;
  for (size_t j = 0; j < b.size(); ++j) scale = std::max(scale, std::abs(b[j] / extent[j % 3]));
  if (!(scale > 0.0)) return false;
  // The weights b will get (as unrounded): half a step of 8 bits at the largest of them, on
  // all three axes, against an eighth of the tolerance.
  double b2 = 0.0, heaviest = 0.0;
  for (double x : b) b2 += x * x;
  for (const std::vector<float>& r : *residual) {
    double along = 0.0;
    for (size_t j = 0; j < r.size(); ++j) along += double(r[j]) * b[j];
    heaviest = std::max(heaviest, std::abs(along / b2));
  }
  const double widest = std::max({extent[0], extent[1], extent[2]});
  const double step = scale * widest / 127.0;
  const int levels = 0.5 * step * heaviest * std::sqrt(3.0) <= tolerance / 8.0 ? 127 : 32767;
  std::vector<int16_t> q(b.size());
  std::vector<double> dequantized(b.size());
  double norm = 0.0;
  for (size_t j = 0; j < b.size(); ++j) {
    q[j] = int16_t(std::lround(b[j] / extent[j % 3] / scale * levels));
    dequantized[j] = double(q[j]) / levels * scale * extent[j % 3];
    norm += dequantized[j] * dequantized[j];
  }
  if (!(norm > 0.0)) return false;
  for (size_t k = 0; k < residual->size(); ++k) {
    std::vector<float>& r = (*residual)[k];
    double along = 0.0;
    for (size_t j = 0; j < r.size(); ++j) along += double(r[j]) * dequantized[j];
    // The weight is written as a float: fit the rest to what the viewer will multiply by.
    const float w = float(along / norm * scale);
    const double c = double(w) / scale;
    for (size_t j = 0; j < r.size(); ++j) r[j] = float(double(r[j]) - c * dequantized[j]);
    out->weights[k].push_back(w);
  }
  out->targets.push_back(std::move(q));
  out->levels.push_back(levels);
  return true;
}

}  // namespace

std::vector<std::vector<double>> symmetric_eigenvectors(std::vector<double> a, size_t n) {
  std::vector<double> v(n * n, 0.0);
  for (size_t i = 0; i < n; ++i) v[i * n + i] = 1.0;
  double total = 0.0;
  for (double x : a) total += x * x;
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off = 0.0;
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
    if (off <= 1e-30 * total) break;
    for (size_t p = 0; p < n; ++p)
      for (size_t q = p + 1; q < n; ++q)
        if (a[p * n + q] != 0.0) jacobi_rotate(a, v, n, p, q);
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return a[x * n + x] > a[y * n + y]; });
  std::vector<std::vector<double>> out;
  for (size_t i : order) {
    std::vector<double> column(n);
    for (size_t k = 0; k < n; ++k) column[k] = v[k * n + i];
    out.push_back(std::move(column));
  }
  return out;
}

MorphTargets fit_morph_targets(Keys residual, const std::array<double, 3>& extent, double tolerance) {
  MorphTargets out;
  out.weights.resize(residual.size());
  out.max_error = largest_distance(residual);
  if (out.max_error <= tolerance || residual.empty()) return out;
  const std::vector<std::vector<double>> components =
      symmetric_eigenvectors(gram(residual), residual.size());
  for (const std::vector<double>& u : components) {
    // The component's displacement field in what is left of the motion.
    std::vector<double> b(residual[0].size(), 0.0);
    for (size_t k = 0; k < residual.size(); ++k)
      if (u[k] != 0.0)
        for (size_t j = 0; j < b.size(); ++j) b[j] += u[k] * residual[k][j];
    if (!add_target(b, extent, tolerance, &residual, &out)) continue;
    out.max_error = largest_distance(residual);
    if (out.max_error <= tolerance) break;
  }
  return out;
}

}  // namespace boreas::gltf
