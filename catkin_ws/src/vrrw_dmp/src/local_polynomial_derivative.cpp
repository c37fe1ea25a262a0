#include <vrrw_dmp/local_polynomial_derivative.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <vrrw_dmp/dmp_error.h>

namespace vrrw_dmp
{
namespace
{
using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 inverse(const Matrix3& m)
{
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  const double inv = 1.0 / det;
  Matrix3 r;
  r[0][0] = c00 * inv;
  r[1][0] = c01 * inv;
  r[2][0] = c02 * inv;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv;
  return r;
}
}  // namespace

LocalPolynomialDerivative::LocalPolynomialDerivative(const std::vector<double>& times, std::size_t half_window)
{
  const std::size_t n = times.size();
  if (n < 3)
    throw DmpError("derivative: " + std::to_string(n) + " samples, the quadratic fit needs at least 3");
  width_ = std::min(n, 2 * std::max<std::size_t>(half_window, 1) + 1);
  begin_.resize(n);
  first_.resize(n * width_);
  second_.resize(n * width_);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t begin = std::min(k - std::min(k, width_ / 2), n - width_);
    begin_[k] = begin;
    const double t0 = times[k];
    const double scale = times[begin + width_ - 1] - times[begin];
    Matrix3 normal{};
    for (std::size_t i = 0; i < width_; ++i)
    {
      const double d = (times[begin + i] - t0) / scale;
      const std::array<double, 3> row{ 1.0, d, d * d };
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          normal[r][c] += row[r] * row[c];
    }
    const Matrix3 inv = inverse(normal);
    for (std::size_t i = 0; i < width_; ++i)
    {
      const double d = (times[begin + i] - t0) / scale;
      first_[k * width_ + i] = (inv[1][0] + inv[1][1] * d + inv[1][2] * d * d) / scale;
      second_[k * width_ + i] = 2.0 * (inv[2][0] + inv[2][1] * d + inv[2][2] * d * d) / (scale * scale);
    }
  }
}

void LocalPolynomialDerivative::apply(const double* values, std::size_t stride, double* first, double* second) const
{
  for (std::size_t k = 0; k < begin_.size(); ++k)
  {
    const double* v = values + begin_[k] * stride;
    const double* w1 = first_.data() + k * width_;
    const double* w2 = second_.data() + k * width_;
    double d1 = 0.0;
    double d2 = 0.0;
    for (std::size_t i = 0; i < width_; ++i)
    {
      d1 += w1[i] * v[i * stride];
      d2 += w2[i] * v[i * stride];
    }
    first[k * stride] = d1;
    second[k * stride] = d2;
  }
}
}  // namespace vrrw_dmp
