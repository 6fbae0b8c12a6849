#pragma once
// A running sum that keeps the rounding error of every addition (Neumaier's compensation, each
// error found by Knuth's TwoSum) and adds it back at the end: a sum of many terms of mixed sign
// loses no more than one rounding. Every shoelace area of the core (tiles, windows, clipped
// pieces) and sums of many tiles' areas are summed so.

#include <cmath>

namespace tessera
{

struct CompensatedSum
{
  double Sum = 0.0;
  double Error = 0.0;
  void Add(double value)
  {
    const double sum = this->Sum + value;
    const double virtualValue = sum - this->Sum;
    this->Error += (this->Sum - (sum - virtualValue)) + (value - virtualValue);
    this->Sum = sum;
  }
  /// a * b with its rounding error recovered exactly by fma (Ogita, Rump and Oishi's Dot2).
  void AddProduct(double a, double b)
  {
    const double product = a * b;
    this->Error += std::fma(a, b, -product);
    this->Add(product);
  }
  double Value() const { return this->Sum + this->Error; }
};

} // namespace tessera
