// A referee header.
