# Previews and reports (harness/report): PNG and OpenEXR output, metrics, HTML. CPU-only.
# The test reads PNGs back with libpng itself, independently of the writer.
find_package(PNG REQUIRED)
glint_add_test_suite(NAME report LABELS unit
  SOURCES
    report/report_test.cpp
    report/report_plot_test.cpp
  LIBS glint_report PNG::PNG OpenEXR::OpenEXR)
