#include "vectors/json_reader.hpp"

#include "vectors/json_escapes.hpp"

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstdint>
#include <limits>
#include <string>
#include <system_error>

namespace vectors {

namespace {

// A JSON number token (already checked against the grammar) as a double:
// std::from_chars where the standard library implements it for floating
// point, else strtod on the token, which reads it the same way (correctly
// rounded, "C" locale: the program never sets another). Debian's emscripten
// ships libc++ 13, which declares from_chars(double&) but does not define it.
struct ParsedDouble {
    double value = 0.0;
    bool out_of_range = false; // beyond a double's range (either way)
    bool whole = false;        // the whole token was read
};

ParsedDouble parse_double(const char* first, const char* last) {
    ParsedDouble parsed;
#if defined(__cpp_lib_to_chars)
    const auto [end, error] = std::from_chars(first, last, parsed.value);
    parsed.out_of_range = error == std::errc::result_out_of_range;
    parsed.whole = error == std::errc() && end == last;
#else
    const std::string token(first, last);
    char* end = nullptr;
    errno = 0;
    parsed.value = std::strtod(token.c_str(), &end);
    parsed.out_of_range = errno == ERANGE;
    parsed.whole = end == token.c_str() + token.size();
#endif
    return parsed;
}

using nlohmann::json;

// Thrown inside this file only; read_json turns it into an Error.
struct SyntaxError {
    std::size_t offset;
    std::string what;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Parser {
public:
    explicit Parser(std::string_view text) : text_(text) {}

    json document() {
        skip_space();
        if (at_end()) {
            fail("the input is empty");
        }
        json value = parse_value(0);
        skip_space();
        if (!at_end()) {
            fail("unexpected text after the document");
        }
        return value;
    }

private:
    bool at_end() const { return pos_ >= text_.size(); }
    char peek() const { return at_end() ? '\0' : text_[pos_]; }
    [[noreturn]] void fail(std::string what) const { throw SyntaxError{pos_, std::move(what)}; }

    void skip_space() {
        while (!at_end()) {
            const char c = text_[pos_];
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
                return;
            }
            ++pos_;
        }
    }

    void expect_literal(std::string_view word) {
        if (text_.substr(pos_, word.size()) != word) {
            fail("unexpected character");
        }
        pos_ += word.size();
    }

    json parse_value(int depth) {
        if (++values_ > kMaxJsonValues) {
            fail("the document holds more than " + std::to_string(kMaxJsonValues) + " values");
        }
        switch (peek()) {
        case '{': return parse_object(depth + 1);
        case '[': return parse_array(depth + 1);
        case '"': return json(parse_string());
        case 't': expect_literal("true"); return json(true);
        case 'f': expect_literal("false"); return json(false);
        case 'n': expect_literal("null"); return json(nullptr);
        default:
            if (peek() == '-' || is_digit(peek())) {
                return json(parse_number());
            }
            fail(at_end() ? "unexpected end of input, expected a value" : "unexpected character, expected a value");
        }
    }

    void check_depth(int depth) const {
        if (depth > kMaxJsonDepth) {
            fail("arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        }
    }

    // `open` (at pos_), then items up to `close`, separated by ','; parse_item() reads each.
    template <class ParseItem>
    void parse_items(int depth, char close, const char* expected, const ParseItem& parse_item) {
        check_depth(depth);
        ++pos_; // '{' or '['
        skip_space();
        if (peek() == close) {
            ++pos_;
            return;
        }
        for (;;) {
            skip_space();
            parse_item();
            skip_space();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            if (peek() == close) {
                ++pos_;
                return;
            }
            fail(expected);
        }
    }

    json parse_object(int depth) {
        json object = json::object();
        parse_items(depth, '}', "expected ',' or '}'", [&] {
            if (peek() != '"') {
                fail("expected a key string");
            }
            const std::size_t key_offset = pos_;
            std::string key = parse_string();
            if (object.contains(key)) {
                throw SyntaxError{key_offset, "duplicate key \"" + key + "\""};
            }
            skip_space();
            if (peek() != ':') {
                fail("expected ':'");
            }
            ++pos_;
            skip_space();
            object[key] = parse_value(depth);
        });
        return object;
    }

    json parse_array(int depth) {
        json array = json::array();
        parse_items(depth, ']', "expected ',' or ']'", [&] { array.push_back(parse_value(depth)); });
        return array;
    }

    // number = [ "-" ] int [ frac ] [ exp ]; int = "0" / digit1-9 *digit
    double parse_number() {
        const std::size_t start = pos_;
        const bool negative = peek() == '-';
        if (negative) {
            ++pos_;
        }
        // Decimal magnitude bookkeeping for out-of-range numbers: the value
        // is about 10^(integer digits after leading zeros + exponent).
        long long magnitude = 0;
        bool seen_nonzero = false;
        if (peek() == '0') {
            ++pos_;
        } else if (is_digit(peek())) {
            while (is_digit(peek())) {
                seen_nonzero = true; // a first digit 1-9
                ++magnitude;
                ++pos_;
            }
        } else {
            fail("expected a digit");
        }
        if (is_digit(peek())) {
            fail("a number must not have leading zeros");
        }
        if (peek() == '.') {
            ++pos_;
            if (!is_digit(peek())) {
                fail("expected a digit after '.'");
            }
            while (is_digit(peek())) {
                if (!seen_nonzero) {
                    if (peek() != '0') {
                        seen_nonzero = true;
                    } else {
                        --magnitude;
                    }
                }
                ++pos_;
            }
        }
        long long exponent = 0;
        if (peek() == 'e' || peek() == 'E') {
            ++pos_;
            bool exponent_negative = false;
            if (peek() == '+' || peek() == '-') {
                exponent_negative = peek() == '-';
                ++pos_;
            }
            if (!is_digit(peek())) {
                fail("expected a digit in the exponent");
            }
            while (is_digit(peek())) {
                if (exponent < 1000000000LL) { // saturate: far beyond any double
                    exponent = exponent * 10 + (peek() - '0');
                }
                ++pos_;
            }
            if (exponent_negative) {
                exponent = -exponent;
            }
        }
        const char* first = text_.data() + start;
        const char* last = text_.data() + pos_;
        const ParsedDouble parsed = parse_double(first, last);
        double value = parsed.value;
        if (parsed.out_of_range) {
            // Too large: +-infinity (the contract's "1e999"); too small: +-0.
            const bool overflow = seen_nonzero && magnitude + exponent > 0;
            value = overflow ? std::numeric_limits<double>::infinity() : 0.0;
            return negative ? -value : value;
        }
        if (!parsed.whole) {
            throw SyntaxError{start, "malformed number"};
        }
        return value;
    }

    unsigned hex4() {
        unsigned code = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = peek();
            unsigned digit = 0;
            if (c >= '0' && c <= '9') {
                digit = static_cast<unsigned>(c - '0');
            } else if (c >= 'a' && c <= 'f') {
                digit = static_cast<unsigned>(c - 'a' + 10);
            } else if (c >= 'A' && c <= 'F') {
                digit = static_cast<unsigned>(c - 'A' + 10);
            } else {
                fail("expected 4 hex digits after \\u");
            }
            code = code * 16 + digit;
            ++pos_;
        }
        return code;
    }

    static void append_utf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out += static_cast<char>(code);
        } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (code >> 18));
            out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        }
    }

    void parse_escape(std::string& out) {
        ++pos_; // '\'
        const char c = peek();
        ++pos_;
        if (c == '/') {
            out += '/';
            return;
        }
        for (const JsonEscape& escape : kJsonEscapes) {
            if (c == escape.letter) {
                out += escape.character;
                return;
            }
        }
        if (c != 'u') {
            --pos_;
            fail("invalid escape sequence");
        }
        unsigned code = hex4();
        if (code >= 0xDC00 && code <= 0xDFFF) {
            fail("unpaired low surrogate in \\u escape");
        }
        if (code >= 0xD800 && code <= 0xDBFF) {
            if (text_.substr(pos_, 2) != "\\u") {
                fail("unpaired high surrogate in \\u escape");
            }
            pos_ += 2;
            const unsigned low = hex4();
            if (low < 0xDC00 || low > 0xDFFF) {
                fail("unpaired high surrogate in \\u escape");
            }
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        append_utf8(out, code);
    }

    // One UTF-8 encoded character (RFC 3629: no overlongs, no surrogates).
    void copy_utf8(std::string& out) {
        const auto byte = [this](std::size_t i) {
            return pos_ + i < text_.size() ? static_cast<unsigned char>(text_[pos_ + i]) : 0u;
        };
        const unsigned b0 = byte(0);
        int length = 0;
        unsigned low = 0x80, high = 0xBF; // allowed range of the second byte
        if (b0 >= 0xC2 && b0 <= 0xDF) {
            length = 2;
        } else if (b0 >= 0xE0 && b0 <= 0xEF) {
            length = 3;
            low = b0 == 0xE0 ? 0xA0 : 0x80;
            high = b0 == 0xED ? 0x9F : 0xBF;
        } else if (b0 >= 0xF0 && b0 <= 0xF4) {
            length = 4;
            low = b0 == 0xF0 ? 0x90 : 0x80;
            high = b0 == 0xF4 ? 0x8F : 0xBF;
        } else {
            fail("invalid UTF-8 in string");
        }
        for (int i = 1; i < length; ++i) {
            const unsigned b = byte(static_cast<std::size_t>(i));
            const unsigned lo = i == 1 ? low : 0x80u;
            const unsigned hi = i == 1 ? high : 0xBFu;
            if (b < lo || b > hi) {
                fail("invalid UTF-8 in string");
            }
        }
        out.append(text_.substr(pos_, static_cast<std::size_t>(length)));
        pos_ += static_cast<std::size_t>(length);
    }

    std::string parse_string() {
        ++pos_; // opening quote
        std::string out;
        for (;;) {
            if (at_end()) {
                fail("unterminated string");
            }
            const unsigned char c = static_cast<unsigned char>(text_[pos_]);
            if (c == '"') {
                ++pos_;
                return out;
            }
            if (c == '\\') {
                parse_escape(out);
            } else if (c < 0x20) {
                fail("control character in string (escape it)");
            } else if (c < 0x80) {
                out += static_cast<char>(c);
                ++pos_;
            } else {
                copy_utf8(out);
            }
        }
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t values_ = 0;
};

} // namespace

frustum::Result<nlohmann::json> read_json(std::string_view text) {
    try {
        return Parser(text).document();
    } catch (const SyntaxError& e) {
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < e.offset && i < text.size(); ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return frustum::Error{"invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(column) +
                              ": " + e.what};
    }
}

} // namespace vectors
