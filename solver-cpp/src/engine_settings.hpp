// The session's settings the engine reads, as one array of numbers (flags 0 or 1): their index,
// in the order of web/model/sessionSchema.ts SESSION_SETTINGS (every setting that goes with a
// solve request, flags included). Adding a setting that changes the hair: a row there, an index
// here (before the count), and the code that reads it.
#pragma once

#include <cstddef>

namespace hairsketch {

enum EngineSetting : size_t {
  kSettingAvoidScalp,   // read by the worker (scalp avoidance), not by the engine
  kSettingFall,         // natural fall (HairEngine::setFall)
  kSettingSections,     // ties may gather their whole scalp section (HairEngine::setSections)
  kSettingFinish,       // finished edges: ends spread near a cut line (HairEngine::setFinish)
  kSettingBust,         // hair rests on the body (HairEngine::setBust, setBody)
  kSettingShape,        // the shape rules (HairEngine::setShape, hair_fall.hpp ShapeRules)
  kSettingVolume,       // their lift at the roots, world units (HairEngine::setShape)
  kSettingTies,         // ties from any hand (HairEngine::setTies)
  kSettingHairline,     // a soft hairline (HairEngine::setHairline, soft_hairline.hpp)
  kSettingCurlVolume,   // curly hair spreads towards its ends (HairEngine::setCurlVolume)
  kSettingNape,         // a low nape: read by the app's head (the scalp mask), not by the engine
  kSettingCoilVolume,   // coily hair stands out from the head (HairEngine::setCoilVolume)
  kSettingRoundPlaits,  // a braid's sections are round across their own path (setRoundPlaits)
  kSettingTieVolume,    // a tie's hair holds a stylist's volume (HairEngine::setTieVolume)
  kSettingCompactBun,   // a bun is a round knot of wraps (HairEngine::setCompactBun)
  kSettingClumpAll,     // every strand finds a clump whose path it shares (setClumpAll)
  kSettingFaceClear,    // governed hair parts round the face too (HairEngine::setFaceClear)
  kSettingLocks,        // detail keeps strands within their length (HairEngine::setLocks)
  kEngineSettingCount
};

}  // namespace hairsketch
