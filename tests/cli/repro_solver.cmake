# Regression tests of the reproducers in ../shared/repro (issue 47), area: solver.
# Inputs are copied into tests/data/repro/<folder>; each test states the expected behaviour.
set(R ${PROJECT_SOURCE_DIR}/tests/data/repro)

# 6. closest never names a candidate that an undecided box may beat: the ridge point (0, 1/2, 0) at
# d^2 >= 9/16 was named while two undecided boxes had d^2 <= 1/2 + 5e-22 (the feet near x = +-1/2
# lie 1e-25 from split lines). Now the foot at x > 0 is certified (the cluster's hull inflated) at
# d^2 = 1/2 - 1e-25; with 40 boxes per system the feet stay undecided and "closest" is empty.
cli_test(repro_solver_closest_foot 0 [=["closest":\[\{"certificate":"Krawczyk: exactly one simple root in the box".*"point":\["2658455991569831745807614652251886999/5316911983139663491615228241121378304","1/2",.*"closest_certified":true.*"distance_approx":0.7071067811865476]=]
         ${CLI} project --point 1/10000000000000000000000000,1/2,3/4 ${R}/solver/pcyl.json)
cli_test(repro_solver_closest_undecided 0 [=["closest":\[\],"closest_certified":false.*"undecided_closest":\[\{.*"verdict":"not certified: 5 undecided box\(es\) may hold the closest point]=]
         ${CLI} project --max-boxes 40 --point 1/10000000000000000000000000,1/2,3/4 ${R}/solver/pcyl.json)
# 7. The pole of a surface of revolution (collapsed edge; from a point on the axis the longitude
# equation vanishes identically): answered at d^2 = 1, not refused as "every point critical".
cli_test(repro_solver_pole 0 [=["closest":\[\{"certificate":"a corner of the stratum","distance2":\{"hi":"1","lo":"1"\},"parameters":\["1","0"\],"point":\["0","0","1"\].*"distance2":\{"hi":"1","lo":"1"\}]=]
         ${CLI} project --point 0,0,2 ${R}/solver/octant.json)
# 8. Double: a point on the saddle has distance about 0 with an outward, non-inverted enclosure
# (was {lo 5.9e-32, hi -9.9e-17} and distance_approx 0.619); intersecting surfaces are found (was
# "intersecting": false with d^2 = -1.49e-16).
cli_test(repro_solver_double_on_surface 0 [=["closest":\[\{"certificate":"none \(double\)","distance2":\{"hi":[0-9.]+e-3[0-9],"lo":[0-9.]+e-3[0-9]\}.*"distance2":\{"hi":[0-9.]+e-3[0-9],"lo":[0-9.]+e-3[0-9]\},"distance_approx":[0-9.]+e-1[0-9]]=]
         ${CLI} project --arith double --point -10/7,-6/7,8/49 ${R}/solver/saddle.json)
cli_test(repro_solver_double_intersecting 0 [=["distance2":\{"hi":0\.0,"lo":0\.0\}.*"intersecting":true.*"verdict":"not certified: the subdivision ran in double. a common point was found]=]
         ${CLI} contact --arith double ${R}/solver/bicubic2.json ${R}/solver/cut_plane.json)
# 9. Surfaces 2^-20 apart: the pair is certified at d^2 = 2^-40 (was: "0 pairs may be the closest").
cli_test(repro_solver_nearly_touching 0 [=["closest":\[\{"certificate":"exact root, certified simple","distance2":\{"hi":"1/1099511627776","lo":"1/1099511627776"\},"parameters":\["0","0","0","0"\].*"closest_certified":true.*"intersecting":false]=]
         ${CLI} contact ${R}/solver/paraboloid.json ${R}/solver/pl_m2e20.json)
# 10. Curve projection with turning points (a line over the paraboloid through its focal region):
# certified, the traced joins agree (was "the traced joins do not agree" with every count right).
cli_test(repro_solver_curve_folds 0 [=["consistent":true,"loops":1.*"segments":2,.*"verdict":"certified: the end and turning points]=]
         sh -c "printf '{\"type\":\"bspline\",\"degrees\":[1],\"knots\":[[-1,-1,1,1]],\"points\":[[-1,\"1/7\",\"3/2\"],[1,\"2/7\",\"3/2\"]]}' > ${CMAKE_CURRENT_BINARY_DIR}/repro_solver_line.json && ${CLI} project --curve ${CMAKE_CURRENT_BINARY_DIR}/repro_solver_line.json ${R}/solver/paraboloid.json")
