# depth pyramid suites (being written)
