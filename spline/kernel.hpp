// Everything of the generic kernel, declarations only.
#pragma once
#include "spline/arith.hpp"
#include "spline/bezier.hpp"
#include "spline/bspline.hpp"
#include "spline/compose.hpp"
#include "spline/elevate.hpp"
#include "spline/evaluate.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"
#include "spline/knots.hpp"
#include "spline/limits.hpp"
#include "spline/trimmed_compose.hpp"
