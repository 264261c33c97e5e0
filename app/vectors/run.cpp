#include "vectors/run.hpp"

#include "vectors/evaluate.hpp"
#include "vectors/json_reader.hpp"
#include "vectors/json_writer.hpp"
#include "vectors/parse_request.hpp"
#include "vectors/response.hpp"

#include "text/one_line.hpp"

#include <istream>
#include <ostream>

namespace vectors {

namespace {

constexpr const char* kPrefix = "frustum-vectors: ";

// Reads all of `in`, refusing more than kMaxInputBytes.
frustum::Result<std::string> read_all(std::istream& in) {
    std::string text;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        const auto got = static_cast<std::size_t>(in.gcount());
        if (text.size() + got > kMaxInputBytes) {
            return frustum::Error{"input is larger than 64 MiB (" + std::to_string(kMaxInputBytes) + " bytes)"};
        }
        text.append(buffer, got);
    }
    if (in.bad()) {
        return frustum::Error{"cannot read the input"};
    }
    return text;
}

} // namespace

const char* usage_text() {
    return R"(usage: frustum-vectors [--help] < request.json > response.json

Reads one JSON request on standard input and writes one JSON response on
standard output: for each case the matrix pair (column-major, as GLM stores
it), the normalized inward planes, the corners C1..C8, the centre D, the
vanishing points O, O1, O2, the section 5.5 validity, and for given points
their clip coordinates and whether they are inside. The computation runs in
double. The contract is docs/vectors-contract.md; in short:

  {"cases": [{"id": "name", "depth": "zero_to_one",
              "camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5,
                                         "near": 0.1, "far": null}},
              "view": {"eye": [0,1,5], "target": [0,0,0], "up": [0,1,0]},
              "ops": [{"mirror": {"plane": [0,1,0,0]}}],
              "points": [[0,0,-3]]}]}

  depth:  zero_to_one (default) | minus_one_to_one | reversed_zero_to_one
  camera: exactly one of
          perspective {fovy_deg (vertical, degrees), aspect, near, far|null}
          frustum     {left, right, bottom, top, near, far|null}
          ortho       {left, right, bottom, top, near, far}
          planes      {left, right, bottom, top, near: [a,b,c,d],
                       and far_point: [x,y,z] or far: "volume"}
          mirror_rect {corner, a1, a2, eye: [x,y,z], far, fit: "paper"|"exact"}
          matrix      [16 numbers, column-major]
  view:   optional {eye, target, up}; the matrix is P * V
  ops:    optional, in order: {"crop": {x, y, width, height, full_width,
          full_height}} (offset from the bottom-left), {"reflect": {plane}},
          {"clip": {plane}}, {"mirror": {plane}}; plane = [a,b,c,d];
          version 2: {"jitter": {dx, dy, full_width, full_height}} (pixels,
          + is right/up), {"portal": {entry: FRAME, exit: FRAME}} with
          FRAME = {origin, x, y} (x, y unit and orthogonal within 1e-6)
  points: optional [[x,y,z], ...]
  rects:  optional (version 2) [{corners: [[x,y,z] x 3+], full_width,
          full_height}]: answered by "screen_rects", {x, y, width, height}
          in pixels from the bottom-left, or null when nothing is visible
  boxes:  optional (version 2) [{min: [x,y,z], max: [x,y,z]}]: answered by
          "cull", "outside" | "intersect" | "inside" per box

Choices where the contract leaves room:
  - "id" (a string) and "camera" are required; every other top-level,
    case, camera and op key is checked, and an unknown key is an error.
  - "far" is required for perspective and frustum: null means infinite.
  - A "view" with the world-space cameras planes, mirror_rect and matrix is
    a malformed request (exit 2), like any key a camera does not take.
  - A number too large for a double (1e999) is infinity and makes its case
    ok: false; "NaN" or "Infinity" as strings are wrong types (exit 2).
  - A key repeated in one object is malformed JSON (exit 2).
  - "inside": every normalized plane (n, d), far plane only when finite,
    has n.p + d >= -1e-6 (|p| + |d|).
  - "clip" and "inside" appear when "points" is given (even empty); the
    same for "screen_rects" with "rects" and "cull" with "boxes".
  - A screen rectangle seen only edge-on (zero width or height) is null.
  - A box with a non-finite coordinate or min > max makes its case ok: false.
  - A case whose answer would hold a non-finite number is ok: false.
  - ok: false errors read "<where>: <library message>", where is camera.<kind>,
    view, ops[i].<op>, points[i], rects[i], boxes[i], planes or result.

Exit status:
  0  the request was well-formed (each case has "ok": true or false)
  1  reading standard input or writing standard output failed
  2  bad arguments, malformed JSON, an unknown key, a wrong type, a missing
     key, or an input larger than 64 MiB; a message on standard error names
     the place (e.g. cases[2].camera.perspective.fovy_deg) and nothing is
     written to standard output
)";
}

int run_frustum_vectors(std::istream& in, std::ostream& out, std::ostream& err) {
    const auto input = read_all(in);
    if (!input) {
        err << kPrefix << text::one_line(input.error()) << '\n';
        return in.bad() ? kExitIoError : kExitBadInput;
    }
    const auto document = read_json(*input);
    if (!document) {
        err << kPrefix << text::one_line(document.error()) << '\n';
        return kExitBadInput;
    }
    const auto request = parse_request(*document);
    if (!request) {
        err << kPrefix << text::one_line(request.error()) << '\n';
        return kExitBadInput;
    }
    std::vector<Outcome> outcomes;
    outcomes.reserve(request->cases.size());
    for (const Case& c : request->cases) {
        outcomes.push_back(evaluate_case(c));
    }
    out << write_json(response_json(outcomes));
    out.flush();
    if (!out) {
        err << kPrefix << "cannot write the output\n";
        return kExitIoError;
    }
    return kExitOk;
}

int frustum_vectors_cli(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err) {
    if (args.size() == 1 && (args[0] == "--help")) {
        out << usage_text();
        out.flush();
        return out ? kExitOk : kExitIoError;
    }
    if (!args.empty()) {
        err << kPrefix << "unexpected argument \"" << args[0]
            << "\" (the request is read from standard input; see --help)\n";
        return kExitBadInput;
    }
    return run_frustum_vectors(in, out, err);
}

} // namespace vectors
