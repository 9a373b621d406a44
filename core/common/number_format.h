#pragma once
// The one number formatter: a figure as text, to a number of decimals or of
// significant digits, with its unit. Every layer formats numbers through it
// (the tablet's word-level formatting in ui/widgets/format.h builds on it), so the
// same value reads the same in a report, a message and on a screen.
//
// The text is the C library's ("%.*f", "%.*g"): a value that rounds to zero
// keeps its sign ("-0.0"), and non-finite values read "nan", "inf", "-inf".
// `unit` is appended as given, so the caller says whether a space separates
// it (" m", " mm", "°", " %").
#include <string>
#include <string_view>

namespace rockface {

// `decimals` places after the point ("%.*f"): format_fixed(12.345, 1, " m")
// is "12.3 m", format_fixed(199.9, 0) is "200".
std::string format_fixed(double v, int decimals, std::string_view unit = {});

// `digits` significant digits, trailing zeros dropped and powers of ten for
// very large or small values ("%.*g"): format_significant(0.012345, 3) is
// "0.0123", format_significant(1234567, 3) is "1.23e+06".
std::string format_significant(double v, int digits, std::string_view unit = {});

// `decimals` places, zero-padded on the left to at least `width` characters
// ("%0*.*f"): bearings and dip directions as a geologist writes them,
// format_zero_padded(45, 5, 1, "°") is "045.0°", format_zero_padded(7, 2, 0)
// is "07"; a longer value is never cut (format_zero_padded(1234.5, 3, 1) is
// "1234.5").
std::string format_zero_padded(double v, int width, int decimals, std::string_view unit = {});

// The value to 17 significant digits ("%.17g"), which every double reads
// back as itself: the form for numbers written to a file that is read again
// (format_round_trip(0.1) is "0.10000000000000001"; not the shortest such
// text, but the same text every C library writes).
std::string format_round_trip(double v, std::string_view unit = {});

}  // namespace rockface
