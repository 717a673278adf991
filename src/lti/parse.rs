//! Parsing people's text into numbers: complex roots such as `-1+2j`, lists such as
//! `-1+2j, -1-2j, -5`, and coefficient lists such as `1, 7, 15, 25`.
