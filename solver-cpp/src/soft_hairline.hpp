// A soft hairline (a session's `hairline` setting): over the scalp's last centimetre the roots
// thin out and some of those left grow short, fine hairs, as a real hairline does, instead of
// every root of the sampling growing full hair up to a hard, comb-tooth edge.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace hairsketch {

// The band (world units: 1 cm) over which the hair thins towards the scalp's edge.
constexpr float kHairlineWidth = 0.1f;
// At the very edge a root grows full hair with this chance, a short hair with half the rest, and
// none with the other half; the chance of full hair rises to 1 across the band (smoothstep).
constexpr float kHairlineFull = 0.3f;
// The short hairs' length: uniform within these (world units: 1 to 3 cm), seeded per root.
constexpr float kHairlineShortMin = 0.1f, kHairlineShortMax = 0.3f;

// The edges of the scalp on a triangle mesh: edges between a scalp triangle and a triangle that
// is not (or no other triangle): 6 floats each (the two ends).
std::vector<float> scalpEdges(const std::vector<float>& positions,
                              const std::vector<uint32_t>& indices,
                              const std::vector<uint8_t>& scalp);

// Each point's distance to the nearest of `edges` (scalpEdges), capped at `cap` (farther points
// get cap).
std::vector<float> distanceToEdges(const std::vector<Eigen::Vector3f>& points,
                                   const std::vector<float>& edges, float cap);

// What each root of pick (indices into the roots, edge: each root's distance to the scalp's
// edge, ids: each root's sample id, the seed key) grows: pick keeps the roots that grow hair (in
// order) and lengthCap gets, for each of those kept, the longest its hair may grow (infinity:
// full hair; else a short hair's length).
void softHairline(const std::vector<float>& edge, const std::vector<uint32_t>& ids, uint32_t seed,
                  std::vector<uint32_t>& pick, std::vector<float>& lengthCap);

}  // namespace hairsketch
