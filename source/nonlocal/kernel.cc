#include <ltn/nonlocal/kernel.h>

#include <cmath>

namespace ltn
{
  Kernel::Kernel(const KernelKind   kind,
                 const double       fractional_order,
                 const unsigned int dim,
                 const double       horizon)
    : dim(dim)
    , eps(horizon)
  {
    switch (kind)
      {
        case KernelKind::constant:
          beta = 0;
          break;
        case KernelKind::inverse_distance:
          beta = 1;
          break;
        case KernelKind::fractional:
          beta = dim + 2 * fractional_order;
          break;
      }

    // Second moment: c/dim * |S| * int_0^eps r^(dim+1-beta) dr = 1.
    c = dim * (dim + 2 - beta) /
        (unit_sphere_area(dim) * std::pow(eps, dim + 2 - beta));
  }



  double
  Kernel::value(const double r) const
  {
    return (r <= eps) ? c * std::pow(r, -beta) : 0.;
  }



  double
  Kernel::exponent() const
  {
    return beta;
  }



  double
  Kernel::scale() const
  {
    return c;
  }



  double
  Kernel::horizon() const
  {
    return eps;
  }



  double
  Kernel::unit_sphere_area(const unsigned int dim)
  {
    static const double area[] = {2., 2. * M_PI, 4. * M_PI};
    return area[dim - 1];
  }



  double
  Kernel::plane_wave_symbol(const double wave_number) const
  {
    // sigma(k) = 2 c |S| int_0^eps r^(dim-1-beta) <cos(k r w_1) - 1>_w dr,
    // with <w_1^{2n}> = Gamma(n+1/2) Gamma(dim/2) / (sqrt(pi) Gamma(n+dim/2))
    // the spherical mean of the 2n-th power of one direction cosine. Term by
    // term:
    //   sum_{n>=1} (-1)^n <w_1^{2n}> (k eps)^{2n} / (2n)!
    //              * eps^(dim-beta) / (2n + dim - beta).
    const long double x = static_cast<long double>(wave_number) * eps;
    long double       power_over_factorial = 1; // (k eps)^{2n} / (2n)!
    long double       spherical_mean       = 1; // <w_1^{2n}>
    long double       sum                  = 0;
    for (unsigned int n = 1; n < 400; ++n)
      {
        power_over_factorial *= x * x / ((2. * n - 1) * (2. * n));
        spherical_mean *= (n - 0.5L) / (n - 1 + 0.5L * dim);
        const long double term = ((n % 2 == 1) ? -1 : 1) * spherical_mean *
                                 power_over_factorial / (2. * n + dim - beta);
        sum += term;
        if (n > x && std::abs(term) < 1e-22L * std::abs(sum))
          break;
      }
    return static_cast<double>(2 * c * unit_sphere_area(dim) *
                               std::pow(eps, dim - beta) * sum);
  }
} // namespace ltn
