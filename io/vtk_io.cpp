#include "io/vtk_io.hpp"

#include <cstdio>
#include <sstream>
#include <vector>

#include "float/mpfr.hpp"
#include "spline/bezier.hpp"

namespace splinex {

std::size_t vtk_hex_index(int i, int j, int k, const std::array<int, 3>& order) {
  // vtkHigherOrderHexahedron::PointIndexFromIJK (VTK 9); tests/vrep/test_vtk.py checks it against VTK itself.
  const bool ibdy = i == 0 || i == order[0], jbdy = j == 0 || j == order[1], kbdy = k == 0 || k == order[2];
  const int nbdy = (ibdy ? 1 : 0) + (jbdy ? 1 : 0) + (kbdy ? 1 : 0);
  if (nbdy == 3) return static_cast<std::size_t>((i ? (j ? 2 : 1) : (j ? 3 : 0)) + (k ? 4 : 0));
  int offset = 8;
  if (nbdy == 2) {
    if (!ibdy) return static_cast<std::size_t>((i - 1) + (j ? order[0] + order[1] - 2 : 0) + (k ? 2 * (order[0] + order[1] - 2) : 0) + offset);
    if (!jbdy)
      return static_cast<std::size_t>((j - 1) + (i ? order[0] - 1 : 2 * (order[0] - 1) + order[1] - 1) +
                                      (k ? 2 * (order[0] + order[1] - 2) : 0) + offset);
    offset += 4 * (order[0] - 1) + 4 * (order[1] - 1);
    return static_cast<std::size_t>((k - 1) + (order[2] - 1) * (i ? (j ? 2 : 1) : (j ? 3 : 0)) + offset);
  }
  offset += 4 * (order[0] - 1 + order[1] - 1 + order[2] - 1);
  if (nbdy == 1) {
    if (ibdy) return static_cast<std::size_t>((j - 1) + (order[1] - 1) * (k - 1) + (i ? (order[1] - 1) * (order[2] - 1) : 0) + offset);
    offset += 2 * (order[1] - 1) * (order[2] - 1);
    if (jbdy) return static_cast<std::size_t>((i - 1) + (order[0] - 1) * (k - 1) + (j ? (order[2] - 1) * (order[0] - 1) : 0) + offset);
    offset += 2 * (order[2] - 1) * (order[0] - 1);
    return static_cast<std::size_t>((i - 1) + (order[0] - 1) * (j - 1) + (k ? (order[0] - 1) * (order[1] - 1) : 0) + offset);
  }
  offset += 2 * ((order[1] - 1) * (order[2] - 1) + (order[2] - 1) * (order[0] - 1) + (order[0] - 1) * (order[1] - 1));
  return static_cast<std::size_t>(offset + (i - 1) + (order[0] - 1) * ((j - 1) + (order[1] - 1) * (k - 1)));
}

namespace {

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// x as the double nearest to it (exact for double; through the exact rational otherwise).
template <class T>
double dbl(const T& x) {
  return to_double(ArithTraits<T>::to_rational(x));
}

}  // namespace

template <class T>
std::string vmodel_to_vtu(const VModel<T>& M) {
  std::vector<double> pts, weights;
  std::vector<std::vector<double>> attrs;
  std::vector<std::array<int, 3>> degrees;
  std::vector<std::size_t> offsets, vcell;
  int q = 3;
  for (const auto& c : M.cells) q = std::max(q, M.trivariates[c.trivariates.front()].q);
  attrs.resize(q - 3);
  std::size_t total = 0;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    for (const auto& pc : extract_bezier(V)) {
      const std::array<int, 3> order{pc.spline.degrees[0], pc.spline.degrees[1], pc.spline.degrees[2]};
      const std::size_t n = pc.spline.size();
      std::vector<std::size_t> slot(n);
      for (int k = 0; k <= order[2]; ++k)
        for (int j = 0; j <= order[1]; ++j)
          for (int i = 0; i <= order[0]; ++i)
            slot[vtk_hex_index(i, j, k, order)] = static_cast<std::size_t>(i + (order[0] + 1) * (j + (order[1] + 1) * k));
      for (std::size_t s = 0; s < n; ++s) {
        const std::size_t m = slot[s];
        for (int d = 0; d < 3; ++d) pts.push_back(dbl(pc.spline.points[m * V.q + d]));
        weights.push_back(pc.spline.is_rational() ? dbl(pc.spline.weights[m]) : 1.0);
        for (int a = 3; a < q; ++a) attrs[a - 3].push_back(a < V.q ? dbl(pc.spline.points[m * V.q + a]) : 0.0);
      }
      total += n;
      offsets.push_back(total);
      degrees.push_back(order);
      vcell.push_back(c);
    }
  }
  std::ostringstream o;
  auto array = [&](const std::vector<double>& v, const std::string& name, int comps) {
    o << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << comps << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < v.size(); ++i) o << g17(v[i]) << ((i + 1) % comps == 0 ? "\n" : " ");
    o << "</DataArray>\n";
  };
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n";
  o << "<Piece NumberOfPoints=\"" << total << "\" NumberOfCells=\"" << offsets.size() << "\">\n";
  o << "<PointData RationalWeights=\"RationalWeights\">\n";
  array(weights, "RationalWeights", 1);
  for (int a = 3; a < q; ++a) array(attrs[a - 3], "attribute_" + std::to_string(a - 3), 1);
  o << "</PointData>\n<CellData HigherOrderDegrees=\"HigherOrderDegrees\">\n";
  std::vector<double> deg;
  for (const auto& d : degrees) deg.insert(deg.end(), {double(d[0]), double(d[1]), double(d[2])});
  array(deg, "HigherOrderDegrees", 3);
  std::vector<double> vc(vcell.begin(), vcell.end());
  array(vc, "vcell", 1);
  o << "</CellData>\n<Points>\n";
  array(pts, "Points", 3);
  o << "</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < total; ++i) o << i << ((i + 1) % 16 == 0 ? "\n" : " ");
  o << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (auto off : offsets) o << off << "\n";
  o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < offsets.size(); ++i) o << "79\n";
  o << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return o.str();
}

template std::string vmodel_to_vtu(const VModel<Rational>&);
template std::string vmodel_to_vtu(const VModel<double>&);
template std::string vmodel_to_vtu(const VModel<Mpfr>&);

}  // namespace splinex
