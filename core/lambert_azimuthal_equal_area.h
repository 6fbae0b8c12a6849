#pragma once
// The Lambert azimuthal equal-area projection of the ellipsoid, oblique, equatorial and polar
// aspects in one formula (Snyder 1987, "Map projections: a working manual", pp. 187-190; EPSG
// method 9820, e.g. EPSG:3035, ETRS89-extended / LAEA Europe). GeographicLib 2.1 has no such
// class; this one follows its projections' calling shape (Forward(lon0, lat, lon, x, y)).
//
// The ellipsoid is first mapped to the authalic sphere (radius Rq, latitude the authalic one:
// equal areas), then the sphere's azimuthal equal-area projection about the centre is stretched
// by D along x and 1/D along y, so that the scale is true in every direction at the centre:
//
//     ellipsoid --(authalic latitude)--> sphere of radius Rq --(spherical LAEA)--> (x', y')
//                                                 x = D x',  y = y' / D
//
// Both steps keep areas, so plane areas are ellipsoidal areas. Angles and latitudes go through
// unit vectors and atan2, not asin, so that points near the poles or the centre keep their digits.

#include <GeographicLib/Ellipsoid.hpp>

namespace tessera
{

class LambertAzimuthalEqualArea
{
public:
  /// a: equatorial radius (m); f: flattening; lat0: the centre's latitude (degrees, in
  /// [-90, 90]; the caller checks it).
  LambertAzimuthalEqualArea(double a, double f, double lat0);

  /// lat, lon (degrees) to x, y (metres) about the centre (lat0, lon0). The centre's antipode
  /// (to within some 0.3 m) has no image: x and y are then NaN, for the caller to refuse.
  void Forward(double lon0, double lat, double lon, double& x, double& y) const;
  /// x, y (metres) to lat, lon (degrees, lon within 180 of lon0). A point beyond the image's rim
  /// (2 Rq from the centre on the sphere, past rounding) gives NaN.
  void Reverse(double lon0, double x, double y, double& lat, double& lon) const;

  /// The authalic sphere's radius (m): the sphere of the ellipsoid's area.
  double AuthalicRadius() const { return this->Rq; }

private:
  GeographicLib::Ellipsoid Earth;
  double Rq;
  double D;      ///< x stretch (1 in the polar aspect)
  double Xi0;    ///< the centre's authalic latitude (degrees)
  double SinXi0; ///< sine of the centre's authalic latitude
  double CosXi0; ///< its cosine
};

} // namespace tessera
