# SSSR: the CPU-generated tables (blue-noise tile, split-sum DFG table).
glint_add_test_suite(NAME sssr_tables LABELS unit SOURCES sssr/tables_test.cpp LIBS glint_core)
