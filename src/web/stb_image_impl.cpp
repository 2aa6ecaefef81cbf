// stb_image and stb_image_write for the WebAssembly build: Debian's libstb holds their
// implementations for the native build, and here they are compiled from the same installed
// headers (Debian's libstb-dev) into rt's module.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
