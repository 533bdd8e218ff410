// An independent oracle for SPEC §6's subsurface check (host, tests only): the reflectance R(α) = E[α^k; k ≤ 256]
// of random walks in the half-space z < 0, in double precision with its own generator (std::mt19937_64) and
// none of the renderer's samplers; and Chandrasekhar's H-function value of the same quantity without the cap.
#pragma once

#include <cstdint>

namespace trazo {

// How a walk enters at the origin: §6's cosine-distributed direction about −z, or straight down −z (a misreading
// of "lit head-on" the tests use as a negative check).
enum class HalfspaceEntry { Cosine, Normal };

// The walks of §6: enter at the origin, take exponential free paths of mean 1 and scatter isotropically k times
// before they first cross z = 0 again; the estimate of E[α^k; k ≤ 256] (a walk still inside after its 256th
// scattering contributes 0; every walk scatters at least once, since it starts downwards). All the albedos are
// estimated from the same `walks` walks; standardErrors (may be null) receives each estimate's standard error.
void halfspaceWalkReflectances(const double* albedos, int count, uint64_t walks, uint64_t seed, double* reflectances,
                               double* standardErrors, HalfspaceEntry entry = HalfspaceEntry::Cosine);

// One albedo.
double halfspaceWalkReflectance(double albedo, uint64_t walks, uint64_t seed, double* standardError = nullptr);

// The same reflectance without the 256-scattering cap, from the H-function of isotropic scattering (Chandrasekhar,
// "Radiative Transfer", 1950): 1 − 2√(1 − α)∫₀¹ H(μ) μ dμ for cosine-distributed entry (1 − √(1 − α)·H(1) for
// Normal). For α ≤ 0.8 the cap changes R by less than 0.8²⁵⁷ ≈ 1e-25, so this checks the walks exactly there.
double halfspaceReflectanceChandrasekhar(double albedo, HalfspaceEntry entry = HalfspaceEntry::Cosine);

}  // namespace trazo
