#pragma once
// Designs of points in the unit cube (0, 1)^d, from which InputDistribution::quantile makes the
// inputs of a sample (simulation/uncertainty/input_distribution.hpp).
//
//   monte-carlo      independent uniform points (GSL's MT19937 seeded with `seed`)
//   latin-hypercube  each coordinate's n values fall one in each of the n strata [k/n, (k+1)/n),
//                    in an independent random order per coordinate, uniform within the stratum
//   sobol            GSL's Sobol sequence (Bratley & Fox 1988, Algorithm 659) from its second
//                    point (0.5, ..., 0.5); deterministic (the seed is not used); at most 40
//                    coordinates; its balance is best for counts that are powers of 2
//
// The same method, count, dimension and seed give the same points on every machine.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

enum class SampleMethod { monte_carlo, latin_hypercube, sobol };

/// "monte-carlo", "latin-hypercube", "sobol" -> the method; else InvalidParameter(`name`, ...).
SampleMethod parse_sample_method(std::string_view method, const std::string& name);
std::string to_string(SampleMethod method);

/// The largest dimension of a Sobol design.
inline constexpr std::size_t max_sobol_dimension = 40;

/// `count` points of (0, 1)^`dims`, point-major: coordinate j of point i is [i * dims + j].
/// Every coordinate lies strictly inside (0, 1). Throws InvalidParameter for dims = 0, or a
/// Sobol design with dims > max_sobol_dimension.
std::vector<double> unit_sample(SampleMethod method, std::size_t count, std::size_t dims, std::uint64_t seed);

}  // namespace hertzdash
