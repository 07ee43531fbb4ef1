/* stb_image compiled into the fuzz targets, so that libFuzzer's coverage and
 * the sanitizers see inside the decoder (Debian's libstb is not
 * instrumented).  The default build links -lstb instead. */
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
