#pragma once
// The digital image of the ridge-grouping field: pixel (i, j) is column i, row j, its centre at
// (OriginX + i * Spacing, OriginY + j * Spacing) in input coordinates, stored at j * Width + i
// (x fastest, as VTK orders image points).

#include "geometry.h"

#include <cstddef>

namespace tessera
{

struct PixelGrid
{
  int Width = 0;
  int Height = 0;
  double OriginX = 0.0;
  double OriginY = 0.0;
  double Spacing = 1.0;

  std::size_t PixelCount() const
  {
    return static_cast<std::size_t>(this->Width) * static_cast<std::size_t>(this->Height);
  }
  std::size_t Index(int i, int j) const
  {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(this->Width) +
      static_cast<std::size_t>(i);
  }
  Point2 PixelCentre(int i, int j) const { return this->FromPixelUnits({ double(i), double(j) }); }
  /// Continuous pixel coordinates to input coordinates (ToPixelUnits' inverse).
  Point2 FromPixelUnits(const Point2& p) const
  {
    return { this->OriginX + p.x * this->Spacing, this->OriginY + p.y * this->Spacing };
  }
  /// Input coordinates to continuous pixel coordinates (pixel centres at integers).
  Point2 ToPixelUnits(const Point2& p) const
  {
    return { (p.x - this->OriginX) / this->Spacing, (p.y - this->OriginY) / this->Spacing };
  }
};

} // namespace tessera
