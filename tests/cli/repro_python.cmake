# Regression tests of the reproducers in ../shared/repro (issue 47), area: python.
# Inputs are copied into tests/data/repro/<folder>; each test states the expected behaviour.
set(R ${PROJECT_SOURCE_DIR}/tests/data/repro)
# The Python module never kills the interpreter and checks its arguments as the CLI does: each
# reproducer now ends in a Python exception naming the field (it was SIGSEGV, a hang, or silence).
if(SPLINEX_PYTHON)
  function(py_repro name regex folder)
    add_test(NAME cli.repro_py_${name} COMMAND ${EXPECT} 1 ${regex} -- bash -c "cd ${R}/${folder} && ulimit -t 30 && python3 repro.py")
    set_tests_properties(cli.repro_py_${name} PROPERTIES ENVIRONMENT PYTHONPATH=${CMAKE_BINARY_DIR}/python)
  endfunction()
  py_repro(deep_nesting [=[ValueError: spline.points(\[0\])+: nests deeper than 64 levels]=] py-deep-nesting-segv)
  py_repro(self_reference [=[ValueError: spline.points(\[0\])+: nests deeper than 64 levels \(or contains itself\)]=] py-self-reference-segv)
  py_repro(structured_case_max_dim [=[ValueError: max_dim: 2147483647 is outside \[1, 3\]]=] py-structured-case-maxdim-hang)
  py_repro(unchecked_precision [=[ValueError: precision: -5 is outside \[2, 100000\]]=] py-unchecked-arguments)
  py_repro(verify_derivative_dir [=[ValueError: dir: 100000 is outside \[0, 2\]]=] py-verify-derivative-dir-segv)
endif()
