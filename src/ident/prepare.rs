//! Preparing a step test for fitting: operating point, step instant and size, window, filter.
