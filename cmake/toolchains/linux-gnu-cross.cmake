# Shared part of the Debian cross toolchains (aarch64-linux-gnu.cmake,
# arm-linux-gnueabihf.cmake): set FRUSTUM_CROSS_TRIPLE and
# FRUSTUM_QEMU first. Test binaries run under qemu-user with the target's
# libraries from the cross sysroot (no binfmt needed), so CTest runs them.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_C_COMPILER ${FRUSTUM_CROSS_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${FRUSTUM_CROSS_TRIPLE}-g++)
set(_sysroot /usr/${FRUSTUM_CROSS_TRIPLE})
set(CMAKE_FIND_ROOT_PATH ${_sysroot})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_CROSSCOMPILING_EMULATOR ${FRUSTUM_QEMU} -L ${_sysroot})
set(CMAKE_PROJECT_INCLUDE ${CMAKE_CURRENT_LIST_DIR}/header-only-deps.cmake)
