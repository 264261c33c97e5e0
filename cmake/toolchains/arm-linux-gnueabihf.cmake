# 32-bit ARM, hard float: Debian's g++-arm-linux-gnueabihf (baseline
# ARMv7-A + VFPv3-D16, no fused multiply-add), run under qemu-arm. Add
# -mfpu=neon-vfpv4 to CMAKE_CXX_FLAGS for NEON and VFPv4's vfma (make test-arm).
#   cmake -S . -B build-arm/armhf -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/arm-linux-gnueabihf.cmake
set(CMAKE_SYSTEM_PROCESSOR arm)
set(FRUSTUM_CROSS_TRIPLE arm-linux-gnueabihf)
set(FRUSTUM_QEMU qemu-arm)
include(${CMAKE_CURRENT_LIST_DIR}/linux-gnu-cross.cmake)
