# SSSR CPU references (classification and brute-force ray march) against hand-worked examples.
glint_add_test_suite(NAME sssr_reference LABELS unit SOURCES sssr/reference_test.cpp reference/sssr_reference.cpp LIBS glint_core)
