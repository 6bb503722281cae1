# Regression tests of the reproducers in ../shared/repro (issue 47), area: cut.
# Inputs are copied into tests/data/repro/<folder>; each test states the expected behaviour.
set(R ${PROJECT_SOURCE_DIR}/tests/data/repro)
# Repro 2: invalid solids are refused while they are read (every cut subcommand), decided exactly.
# A quadratic top facet dipping below the bottom one (crossings at (4/3, 0) and (8/3, 0), not at
# any dyadic parameter: proved by the intermediate value theorem); a straight figure eight of positive
# signed area (the exact crossing point); a single-point facet. Were: a guide "proved" for the first two.
cli_test(repro_cut_self_intersecting 2 [=[^splinex: error: facets\[0\]: crosses facets\[2\] within \[.*the loop is not simple]=]
         ${CLI} cut guide ${R}/cut/self_intersecting.solid.json ${R}/cut/self_intersecting.cut.json)
cli_test(repro_cut_figure_eight 2 [=[^splinex: error: facets\[0\]: meets facets\[2\] at \(8/3, 1\) .*the loop is not simple]=]
         ${CLI} cut guide ${R}/cut/figure_eight.solid.json ${R}/cut/figure_eight.cut.json)
cli_test(repro_cut_figure_eight_facet 2 [=[^splinex: error: facets\[0\]: meets facets\[2\] at \(8/3, 1\)]=]
         ${CLI} cut facet ${R}/cut/figure_eight.solid.json ${R}/cut/figure_eight.cut.json)
cli_test(repro_cut_zero_length_facet 2 [=[^splinex: error: facets\[6\]: is a single point \(0, 0\): a facet of zero length]=]
         ${CLI} cut guide ${R}/cut/zero_length_facet.solid.json ${D}/cut2d_L.json)
# Repro 3: --strip 10 removes every sample: no constraint rows, no boundary piece checked. Both
# verdicts are undecided with the reason (were: "proved" and "certified").
cli_test(repro_cut_strip_everything 0 [=["rows":0,.*"separation":\{"meaning":"nothing was checked: every boundary piece lies in the strip[^}]*"pieces_certified":0,[^}]*"verdict":"undecided"\}.*"verdict":"undecided: the program has no constraint rows]=]
         ${CLI} cut guide --strip 10 ${D}/solid2d_L.json ${D}/cut2d_L.json)
cli_test(repro_cut_strip_everything_double 0 [=["separation":\{"meaning":"nothing was checked[^}]*"verdict":"undecided"\}.*"verdict":"undecided: the program has no constraint rows]=]
         ${CLI} cut guide --arith double --strip 10 ${D}/solid2d_L.json ${D}/cut2d_L.json)
