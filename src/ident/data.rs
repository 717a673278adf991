//! Loading measured step tests from text files.
