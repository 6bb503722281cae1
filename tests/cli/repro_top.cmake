# Regression tests of the reproducers in ../shared/repro (issue 47), area: top.
# Inputs are copied into tests/data/repro/<folder>; each test states the expected behaviour.
# No ';' inside a command: CMake splits arguments there (use && and bash -o pipefail).
set(R ${PROJECT_SOURCE_DIR}/tests/data/repro)
set(JSON_CHECK "python3 ${CMAKE_CURRENT_SOURCE_DIR}/json_check.py")
set(B ${CMAKE_CURRENT_BINARY_DIR})

# --dir was not checked by derivative (SIGSEGV at 100000, undefined behaviour one past the end).
cli_test(repro_derivative_dir_out_of_range 2 [=[^splinex: error: dir: direction 100000 does not exist in a spline of dimension 1]=]
         ${CLI} derivative --dir 100000 ${R}/derivative-dir-out-of-range-segv/curve.json)
cli_test(repro_derivative_dir_one_past 2 [=[^splinex: error: dir: direction 1 does not exist in a spline of dimension 1]=]
         ${CLI} derivative --dir 1 ${R}/derivative-dir-1-wrong-error/curve.json)
cli_test(repro_derivative_dir_negative 2 [=[^splinex: error: dir: direction -1 does not exist]=]
         ${CLI} derivative --dir -1 ${R}/derivative-dir-1-wrong-error/curve.json)
cli_test(repro_verify_derivative_dir 2 [=[^splinex: error: dir: direction 100000 does not exist]=]
         ${CLI} verify derivative --dir 100000 --input ${R}/verify-derivative-dir-out-of-range-segv/curve.json
         --candidate ${R}/verify-derivative-dir-out-of-range-segv/cand.json)
# FLINT under --max-memory: the typed line, not an abort. (Release only: ASan cannot enforce a budget.)
if(NOT SPLINEX_SANITIZE)
cli_test(repro_memcap_flint 2 [=[^splinex: error: memory: out of memory within the budget of 300 MiB]=]
         ${CLI} --max-memory 300M elevate --arith flint --by 99 ${R}/memcap-flint-terminate/doc.json)
set_tests_properties(cli.repro_memcap_flint PROPERTIES TIMEOUT 120)
endif()
# Output folders are checked before the work: one line, no progress before it.
cli_test(repro_sweep_single_out 2 [=[^splinex: error: .*out: the folder name is empty]=]
         bash -c "${CLI} sweep single proofs --cases 1 --out '' > /dev/null 2> ${B}/repro_sweep_out.err || s=$? && cat ${B}/repro_sweep_out.err && test $(wc -l < ${B}/repro_sweep_out.err) -eq 1 && exit $s")
cli_test(repro_sweep_run_dir_is_file 2 [=[^splinex: error: .*dir: .* is a file, not a folder]=]
         bash -c "${CLI} sweep plan proofs --cases 1 > ${B}/repro_sweep_jobs.jsonl && ${CLI} sweep run --jobs ${B}/repro_sweep_jobs.jsonl --dir ${R}/sweep-single-out-checked-after-work/cmd.sh")
# 16,000 loops (two loops repeated): the meeting loops are named in seconds (was quadratic: > 60 s).
cli_test(repro_untrim_duplicate_loops 2 [=[^splinex: error: loops\[2\]: meets loops\[0\]]=]
         bash -c "ulimit -t 30 && ${CLI} untrim ${R}/untrim-duplicate-loops-quadratic-reject/holed_x16000.json")
# A function-level bound beyond double's range is the usual string, never null.
cli_test(repro_verify_bound_overflow 0 [=[^ok$]=]
         bash -o pipefail -c "${CLI} verify reverse --input ${R}/verify-function-bound-overflow-null/m.json --candidate ${R}/verify-function-bound-overflow-null/c.json | ${JSON_CHECK} 'j[\"function\"][\"upper\"].startswith(\"+inf\")' 'j[\"function\"][\"certified\"]' 'j[\"function\"][\"upper_exact\"].startswith(\"1000\")' '\"null\" not in raw'")
# Domain ends rounded to double are compared as rounded interior knots are (was: "different", upper 0).
cli_test(repro_verify_rounded_domain 0 [=[^ok$]=]
         bash -o pipefail -c "${CLI} elevate --by 1 --arith double ${R}/verify-rounded-domain-not-compared/S.json > ${B}/repro_rounded_D.json && ${CLI} verify elevate --by 1 --input ${R}/verify-rounded-domain-not-compared/S.json --candidate ${B}/repro_rounded_D.json | ${JSON_CHECK} 'j[\"structure\"] == \"equal after rounding\"' 'j[\"function\"][\"certified\"]' 'j[\"function\"][\"within_factor\"]' 'float(j[\"function\"][\"upper\"]) > 0' 'float(j[\"function\"][\"bits_lost\"]) < 8'")
# An uncertified bound is absent with its reason, never "upper": 0 (functions on different domains).
cli_test(verify_not_compared_no_upper 0 [=[^ok$]=]
         bash -o pipefail -c "${CLI} reparametrize --interval 0,2 ${R}/verify-rounded-domain-not-compared/S.json > ${B}/repro_moved.json && ${CLI} verify elevate --by 1 --input ${R}/verify-rounded-domain-not-compared/S.json --candidate ${B}/repro_moved.json | ${JSON_CHECK} 'j[\"structure\"] == \"different\"' 'not j[\"function\"][\"certified\"]' '\"upper\" not in j[\"function\"]' 'j[\"function\"][\"upper_note\"].startswith(\"no certified bound\")'")
# Exact subdivision engines refuse numbers longer than --max-input-bits when the model is read (was: a hang).
cli_test(repro_vrep_topology_long_number 2 [=[^splinex: error: .*cells\[0\]\.trivariate\.points\[3\]\[0\]: has a number of (at least )?[0-9]+ bits, over the exact limit of 4096]=]
         bash -c "ulimit -t 20 && ${CLI} vrep topology ${R}/vrep-topology-tiny-coordinate-hang/m.json --boxes 64")
# An output file that is a folder is named as given, before the work (was: '..tmp: Device or resource busy').
cli_test(repro_vrep_ssi_obj_folder 2 [=[^splinex: error: options: --obj: \. is a folder, not a file]=]
         bash -c "cd ${B} && ${CLI} vrep ssi teapot:handle teapot:body --step 1/8 --grid 8 --obj .")
if(NOT SPLINEX_SANITIZE)  # ASan reserves terabytes of address space: no cap under it
# Under an external address-space cap (ulimit -v 50 MiB) the reader's exhaustion is the typed line, not an abort.
cli_test(repro_external_cap 2 [=[^splinex: error: memory: out of memory within the budget of]=]
         bash -c "python3 ${D}/make_document.py long 100000 > ${B}/repro_long.json && ulimit -v 51200 && ${CLI} eval --at 0.5 ${B}/repro_long.json")
endif()
