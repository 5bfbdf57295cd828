// The deep opacity maps' lookup (Yuksel & Keyser 2008), GLSL shared by the strands' shaders
// (strandShaders.ts) and the head's and bust's shadow receivers (hairShadowReceiver.ts): the
// opacity accumulated between the first hair seen from the light and a point `d` behind it
// (world units), interpolated between the 3 layers' cumulative opacities `o`, which end at
// `layers` (deepOpacity.ts builds the maps).
export const DOM_LAYERED_OPACITY_GLSL = /* glsl */ `
float domLayeredOpacity(vec3 o, float d, vec3 layers) {
  if (d < layers.x) return o.r * d / layers.x;
  if (d < layers.y) return mix(o.r, o.g, (d - layers.x) / (layers.y - layers.x));
  if (d < layers.z) return mix(o.g, o.b, (d - layers.y) / (layers.z - layers.y));
  return o.b;
}
`;
