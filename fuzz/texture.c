/* Fuzz target: texture images through the project's loader
 * (common/texture_image.h), which decodes them with stb_image.  Contracts: a
 * decoded image has sides in range and every texel readable; a refused one
 * is left empty, with the problem named. */
#include "fuzz.h"
#include "texture_image.h"

int fuzz_texture(const uint8_t *data, size_t size)
{
    texture_image t;
    char problem[256] = "";
    if (texture_image_decode(data, size, &t, problem, sizeof problem) == 0) {
        fuzz_check(t.rgb && t.width >= 1 && t.height >= 1 && t.width <= TEXTURE_MAX_SIDE &&
                       t.height <= TEXTURE_MAX_SIDE && (long long)t.width * t.height <= TEXTURE_MAX_TEXELS,
                   "decoded %d x %d", t.width, t.height);
        unsigned sum = 0;
        for (int y = 0; y < t.height; y++) /* every texel, so that ASan sees the whole buffer */
            for (int x = 0; x < t.width; x++)
                sum += t.rgb[((size_t)y * (size_t)t.width + (size_t)x) * 3 + 2];
        fuzz_check(sum <= 255u * (unsigned)t.width * (unsigned)t.height, "texel sum");
        texture_image_free(&t);
        return 0;
    }
    fuzz_check(!t.rgb && t.width == 0 && t.height == 0, "a refused image left texels");
    fuzz_check(problem[0] != '\0', "a refused image without a problem named");
    return 0;
}

FUZZ_ENTRY(fuzz_texture)
