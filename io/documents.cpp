#include "io/documents.hpp"

#include <iostream>

#include "io/hybrid_io.hpp"
#include "io/trimmed_domain_io.hpp"

namespace splinex {

BSpline<Rational> read_spline(const std::string& path, const Limits& limits, const ReadLimits& read_limits, const std::string& where) {
  return spline_from_json(read_json_file(path, read_limits), limits, where);
}

HybridPatch<Rational> read_hybrid(const std::string& path, const Limits& limits, const ReadLimits& read_limits) {
  return hybrid_from_json(read_json_file(path, read_limits), limits);
}

TrimmedDomain read_trimmed_domain(const std::string& path, const ReadLimits& read_limits) {
  return trimmed_domain_from_json(read_json_file(path, read_limits));
}

std::string document_text(const Json& doc, int indent) { return doc.dump(indent) + "\n"; }

void print_document(const Json& doc, int indent) { std::cout << document_text(doc, indent); }

Json document(const HybridPatch<Rational>& P) { return hybrid_to_json(P); }

}  // namespace splinex
