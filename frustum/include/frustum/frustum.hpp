// Everything in the frustum library.
#pragma once

#include "frustum/crop.hpp"
#include "frustum/depth_range.hpp"
#include "frustum/from_planes.hpp"
#include "frustum/lens.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/mirror.hpp"
#include "frustum/non_affine.hpp"
#include "frustum/oblique_clip.hpp"
#include "frustum/plane.hpp"
#include "frustum/projection.hpp"
#include "frustum/queries.hpp"
#include "frustum/reflect.hpp"
#include "frustum/result.hpp"
#include "frustum/validate.hpp"
#include "frustum/volume_approximation.hpp"
