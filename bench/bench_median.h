// The median of the benchmarks' repeated timings (the mean of the middle two for an even count).

#ifndef AF_BENCH_MEDIAN_H
#define AF_BENCH_MEDIAN_H

#include <algorithm>
#include <cmath>
#include <vector>

inline double median(std::vector<double> v)
{
  if(v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

#endif // AF_BENCH_MEDIAN_H
