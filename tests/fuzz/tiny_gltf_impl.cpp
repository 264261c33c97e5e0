// tinygltf 2.7.0's implementation, compiled with the fuzzing instrumentation
// (Debian ships it as an uninstrumented libtinygltf.so; this is the same
// header with the same defaults: nlohmann/json and stb_image from libstb).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
