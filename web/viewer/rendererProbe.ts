// What the page renders with: the WebGL renderer's name (a software rasteriser or a GPU) and the
// display's pixel ratio the canvas is drawn at.

/** The unmasked renderer string of a probe context (released at once): tells a software
 *  rasteriser from a GPU. */
export function glRendererName(): string {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return '';
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return name;
}

/** Whether a renderer name (glRendererName) is a software rasteriser (SwiftShader, llvmpipe). */
export function isSoftwareRenderer(name: string): boolean {
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

/** The display's pixel ratio, capped at 2 (more costs fill rate for no visible gain). */
export function basePixelRatio(): number {
  return Math.min(window.devicePixelRatio || 1, 2);
}
