#include "mercator.h"

#include <GeographicLib/Math.hpp>

#include <cmath>

namespace tessera
{

using GeographicLib::Math;

Mercator::Mercator(double a, double f)
  : Earth(a, f)
  , A(a)
{
}

void Mercator::Forward(double lon0, double lat, double lon, double& x, double& y) const
{
  x = this->A * Math::AngDiff(lon0, lon) * Math::degree();
  y = this->A * this->Earth.IsometricLatitude(lat) * Math::degree();
}

void Mercator::Reverse(double lon0, double x, double y, double& lat, double& lon) const
{
  if (!(std::abs(x) <= this->A * Math::pi() * (1.0 + 1e-12)))
  {
    // (beyond 180 degrees from lon0, where Forward puts nothing: x = 1e12 wrapped to a longitude)
    lat = lon = Math::NaN();
    return;
  }
  lon = lon0 + x / this->A / Math::degree();
  lat = this->Earth.InverseIsometricLatitude(y / this->A / Math::degree());
}

} // namespace tessera
