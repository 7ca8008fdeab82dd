#pragma once
// Stroke files (issue 20): the strokes of a sketched flow as users bring them, read for
// `fluidviz sketch` and for scenes with lbm.initial_flow = sketch (lbm.sketch.file).
//
//   .csv  '#' comment lines, a header naming the columns stroke, x, y, speed (any order, other
//         columns ignored), then one point per line: the stroke's number (whole; a stroke's
//         points on consecutive lines, in drawing order), the point (m), the stroke's speed (m/s,
//         the same on every line of a stroke; negative reverses the flow).
//   .vtp  polylines, e.g. drawn in ParaView: every line cell (VTK_LINE or VTK_POLY_LINE) is one
//         stroke, its points in drawing order (z ignored; other cells ignored). Its speed (m/s)
//         is the cell-data array "speed" (1 component), else the point-data array "speed" (the
//         same at every point of a line), else 1 m/s.
//   .svg  every <path> element's d attribute: each subpath (M or m) is one stroke. Commands M, L,
//         H, V, C (cubic Beziers, flattened into kSvgCurveSegments segments) and Z, absolute and
//         relative; others (S, Q, T, A) are refused by name, as is any transform attribute. One
//         user unit is 1 m; y points down in SVG and is flipped within the viewBox (required) so
//         that the drawing appears as it looks: y_m = 2 min_y + height - y. Speed (m/s): the
//         path's data-speed attribute, else 1 m/s.
//
// Hostile input (docs/reliability.md): every problem throws FileError naming the file and what is
// wrong (a missing column, a value that is not a finite number, a point index outside the points,
// a speed that changes along a stroke, no strokes); nothing else escapes.
#include <filesystem>
#include <vector>

#include "filters/sketch/strokes/Stroke.h"

namespace fluidviz::sketch {

/// The speed of a .vtp line without a "speed" array (m/s).
inline constexpr double kDefaultStrokeSpeed = 1.0;

std::vector<Stroke> readStrokesCsv(const std::filesystem::path& file);
std::vector<Stroke> readStrokesVtp(const std::filesystem::path& file);
std::vector<Stroke> readStrokesSvg(const std::filesystem::path& file);
/// The segments a cubic Bezier of an .svg path becomes.
inline constexpr int kSvgCurveSegments = 16;
/// By the extension: .csv, .vtp or .svg; FileError for any other.
std::vector<Stroke> readStrokeFile(const std::filesystem::path& file);

}  // namespace fluidviz::sketch
