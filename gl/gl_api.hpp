// GL types and enums from the Khronos GLES 3.2 headers, without function
// prototypes: every call goes through gl::Functions.
#pragma once

#ifndef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 0
#endif
#include <GLES3/gl32.h>
#include <GLES2/gl2ext.h>

// Desktop GL only: occlusion query counting samples (GLES has only the
// boolean GL_ANY_SAMPLES_PASSED[_CONSERVATIVE]).
#ifndef GL_SAMPLES_PASSED
#define GL_SAMPLES_PASSED 0x8914
#endif
