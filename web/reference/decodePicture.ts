// Decoding a reference picture in the browser, after pictureFile.ts checked its bytes: an
// ImageBitmap flipped for WebGL's bottom-up rows, or one sentence saying why not.
import type { PictureHeader } from './pictureFile';
import { PICTURE_MIME } from './pictureFile';

export async function decodePicture(
  bytes: ArrayBuffer,
  header: PictureHeader,
): Promise<{ ok: true; image: ImageBitmap } | { ok: false; error: string }> {
  let image: ImageBitmap;
  try {
    image = await createImageBitmap(new Blob([bytes], { type: PICTURE_MIME[header.format] }), {
      imageOrientation: 'flipY',
    });
  } catch {
    return {
      ok: false,
      error: `it is a damaged ${header.format.toUpperCase()}: it does not decode`,
    };
  }
  if (image.width !== header.width || image.height !== header.height) {
    // an EXIF rotation swaps the sides: still the picture the header describes
    const swapped = image.width === header.height && image.height === header.width;
    if (!swapped) {
      image.close();
      return { ok: false, error: 'it decodes to another size than its header says' };
    }
  }
  return { ok: true, image };
}
