// The certified projection and contact results as documents (`splinex project`, `splinex
// contact`): the critical points or stationary pairs with their certificates, the enclosure of the
// smallest squared distance and the verdict in words.
#pragma once
#include "io/json_io.hpp"
#include "solve/contact.hpp"
#include "solve/curve_projection.hpp"
#include "solve/projection.hpp"

namespace splinex {

/// A point's projection onto a surface (T: Rational, certified; double, uncertified).
template <class T>
Json projection_document(const ProjectionResult<T>& r);
/// The minimum distance of two surfaces, or their certified common point.
template <class T>
Json contact_document(const ContactResult<T>& r);
/// A curve's projection (Eq. 3): special points, slices, traced branches.
Json curve_projection_document(const CurveProjectionResult& r);

}  // namespace splinex
