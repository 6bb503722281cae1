// Uses an installed splinex::vrep_io (the V-rep facade, docs/vrep.md "From C++"): two V-model
// documents read and validated, intersected exactly (planar cuts where they suffice, else trimmed
// cells), the result's cell count and document size printed.
//   vrep_boolean A.json B.json
#include <iostream>

#include "vrep/io/api.hpp"

int main(int argc, char** argv) {
  using namespace splinex;
  if (argc != 3) {
    std::cerr << "usage: vrep_boolean A.json B.json\n";
    return 2;
  }
  try {
    const auto A = vrep::load_operand(argv[1], Limits{}, ReadLimits{});
    const auto B = vrep::load_operand(argv[2], Limits{}, ReadLimits{});
    vrep::BooleanRequest rq;  // intersect, exact, planar where it suffices
    const auto R = vrep::boolean(A, B, rq);
    const Json doc = vrep::document(R);
    std::cout << "intersection: " << doc.at("cells").size() << " cell(s), " << (std::holds_alternative<VModel<Rational>>(R) ? "planar cuts" : "trimmed cells")
              << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "vrep_boolean: error: " << e.what() << "\n";
    return 2;
  }
}
