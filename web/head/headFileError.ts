// The one error reading a head file throws inside the loader (its message is the reason shown to
// the user), and the triangle cap every format checks before allocating.

/** A head file that cannot be used; the message says why in plain words. */
export class HeadFileError extends Error {}

export function capCheck(triangles: number, maxTriangles: number): void {
  if (triangles > maxTriangles)
    throw new HeadFileError(
      `it has ${triangles.toLocaleString('en-US')} triangles, over the limit of ${maxTriangles.toLocaleString('en-US')}: decimate it first`,
    );
}
