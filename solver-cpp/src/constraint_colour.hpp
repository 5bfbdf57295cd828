// Display colour of a derived constraint (paper Figs. 2, 4, 5), reported next to the merged
// constraint set so the viewer can draw each kind in its colour.
#pragma once

#include <cstdint>

namespace hairsketch {

enum class ConstraintColour : uint8_t {
  Blue = 0,    // stream-curve tangents, dividing Gaussian profile, ponytail spine
  Red = 1,     // stream-curve fading extension, dividing discontinuity (0.3)
  Purple = 2,  // ponytail cross sections (longitudinal)
  Green = 3,   // ponytail centripetal ring
  Extra = 4,   // explicit extra constraints (scalp avoidance)
};

}  // namespace hairsketch
