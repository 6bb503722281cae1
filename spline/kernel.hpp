// Everything of the generic B-spline kernel, declarations only (composition: compose/).
#pragma once
#include "base/limits.hpp"
#include "spline/arith.hpp"
#include "spline/bezier.hpp"
#include "spline/bspline.hpp"
#include "spline/elevate.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"
#include "spline/knots.hpp"
