// The V-rep templates instantiated for the exact and float arithmetics.
#include "float/mpfr.hpp"
#include "vrep/primitives_impl.hpp"
#include "vrep/regularity_impl.hpp"
#include "vrep/vmodel_impl.hpp"
#include "vrep/trivariate_impl.hpp"

namespace splinex {

const char* to_string(Regularity r) {
  return r == Regularity::regular ? "regular" : r == Regularity::singular ? "singular" : "undecided";
}

#define SPLINEX_INSTANTIATE_VREP(T)                                                                                 \
  template BSpline<T> extrude(const BSpline<T>&, const std::vector<T>&, const Limits&);                              \
  template BSpline<T> ruled(const BSpline<T>&, const BSpline<T>&, const Limits&);                                    \
  template BSpline<T> revolve(const BSpline<T>&, int, int, const Limits&);                                           \
  template BSpline<T> rational_circle(int);                                                                          \
  template BSpline<T> boolean_sum(const std::array<std::array<BSpline<T>, 2>, 3>&, const Limits&);                   \
  template BSpline<T> sweep(const std::vector<BSpline<T>>&, const std::vector<T>&, int, const Limits&);              \
  template BSpline<T> face(const BSpline<T>&, int, int);                                                             \
  template RegularityReport<T> certify_regularity(const BSpline<T>&, int, const Limits&);                            \
  template BSpline<T> jacobian_determinant(const BSpline<T>&, const Limits&);                                        \
  template struct VModel<T>;                                                                                         \
  template VModel<T> glue(const std::vector<BSpline<T>>&, const T&, const std::vector<std::string>&, const Limits&);   \
  template VModelCheck check_invariants(const VModel<T>&, const Limits&);                                            \
  template std::size_t surface_of_face(const VModel<T>&, std::size_t, int, int);                                     \
  template std::size_t curve_of_edge(const VModel<T>&, std::size_t, int, const std::array<int, 3>&);                 \
  template void attach_field(VModel<T>&, std::size_t, const std::string&, BSpline<T>, const Limits&);                \
  template CellValue<T> evaluate_cell(const VModel<T>&, std::size_t, const std::vector<T>&);                        \
  template BSpline<T> edge_curve(const BSpline<T>&, int, const std::array<int, 3>&);                                 \
  template bool same_curve(const BSpline<T>&, const BSpline<T>&, const T&, bool, const Limits&);                     \
  template bool same_surface(const BSpline<T>&, const BSpline<T>&, const T&, const Limits&);                         \
  template std::vector<BSpline<T>> disk_cells(const T&);                                                             \
  template std::vector<BSpline<T>> cylinder_cells(const T&, const T&);                                               \
  template std::vector<BSpline<T>> cone_cells(const T&, const T&, const T&);                                         \
  template std::vector<BSpline<T>> torus_cells(const T&, const T&);                                                  \
  template std::vector<BSpline<T>> box_cells(const std::vector<T>&, const std::vector<T>&);                          \
  template BSpline<T> singular_cylinder(const T&, const T&);                                                         \
  template BSpline<T> singular_sphere(const T&);

SPLINEX_INSTANTIATE_VREP(Rational)
SPLINEX_INSTANTIATE_VREP(double)
SPLINEX_INSTANTIATE_VREP(Mpfr)

}  // namespace splinex
