// The code of the header-only libraries the scene loader uses. On the
// desktop it comes from Debian's libtinygltf.so and libstb.so
// (app/scene/CMakeLists.txt); a wasm page cannot link host libraries, so
// the web build compiles it here, as those libraries are built: tinygltf
// with its default stb_image / stb_image_write image code.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
