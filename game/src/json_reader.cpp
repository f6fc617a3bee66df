// A recursive-descent JSON reader (RFC 8259's grammar), enough for files rube writes.
#include "json_reader.hpp"

#include <cctype>
#include <cstdio>

namespace rube::game {

namespace {

class Reader {
public:
    explicit Reader(std::string_view text) : text_(text) {}

    std::optional<JsonValue> document(std::string& error) {
        JsonValue value;
        bool ok = parse(value, 0);
        if (ok) skip();
        if (ok && at_ != text_.size()) ok = fail("text after the value");
        if (!ok) {
            error = where() + ": " + error_;
            return std::nullopt;
        }
        return value;
    }

private:
    static constexpr int kMaxDepth = 64;

    bool fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
        return false;
    }
    std::string where() const {
        int line = 1, column = 1;
        for (std::size_t i = 0; i < at_ && i < text_.size(); ++i) {
            if (text_[i] == '\n') line++, column = 1;
            else ++column;
        }
        return std::to_string(line) + ":" + std::to_string(column);
    }
    void skip() {
        while (at_ < text_.size() &&
               (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\r' || text_[at_] == '\t'))
            ++at_;
    }
    bool literal(std::string_view word) {
        if (text_.substr(at_, word.size()) != word) return fail("unexpected character");
        at_ += word.size();
        return true;
    }
    bool string(std::string& out) {
        ++at_; // the opening quote
        while (at_ < text_.size() && text_[at_] != '"') {
            char c = text_[at_++];
            if (c == '\\') {
                if (at_ >= text_.size()) break;
                const char e = text_[at_++];
                switch (e) {
                case 'n': c = '\n'; break;
                case 't': c = '\t'; break;
                case 'r': c = '\r'; break;
                case 'b': c = '\b'; break;
                case 'f': c = '\f'; break;
                case 'u': return fail("\\u escapes are not read");
                default: c = e;
                }
            }
            out += c;
        }
        if (at_ >= text_.size()) return fail("unterminated string");
        ++at_;
        return true;
    }
    bool number(JsonValue& value) {
        const std::size_t begin = at_;
        while (at_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[at_])) || text_[at_] == '-' ||
                                      text_[at_] == '+' || text_[at_] == '.' || text_[at_] == 'e' || text_[at_] == 'E'))
            ++at_;
        value.type = JsonValue::Type::number;
        value.text = std::string(text_.substr(begin, at_ - begin));
        return at_ > begin || fail("expected a value");
    }
    bool parse(JsonValue& value, int depth) {
        if (depth > kMaxDepth) return fail("nested too deeply");
        skip();
        if (at_ >= text_.size()) return fail("unexpected end");
        const char c = text_[at_];
        if (c == '{') {
            value.type = JsonValue::Type::object;
            ++at_;
            skip();
            if (at_ < text_.size() && text_[at_] == '}') return ++at_, true;
            for (;;) {
                skip();
                std::string key;
                if (at_ >= text_.size() || text_[at_] != '"') return fail("expected a key");
                if (!string(key)) return false;
                skip();
                if (at_ >= text_.size() || text_[at_] != ':') return fail("expected ':'");
                ++at_;
                if (!parse(value.object[key], depth + 1)) return false;
                skip();
                if (at_ < text_.size() && text_[at_] == ',') ++at_;
                else if (at_ < text_.size() && text_[at_] == '}') return ++at_, true;
                else return fail("expected ',' or '}'");
            }
        }
        if (c == '[') {
            value.type = JsonValue::Type::array;
            ++at_;
            skip();
            if (at_ < text_.size() && text_[at_] == ']') return ++at_, true;
            for (;;) {
                value.array.emplace_back();
                if (!parse(value.array.back(), depth + 1)) return false;
                skip();
                if (at_ < text_.size() && text_[at_] == ',') ++at_;
                else if (at_ < text_.size() && text_[at_] == ']') return ++at_, true;
                else return fail("expected ',' or ']'");
            }
        }
        if (c == '"') {
            value.type = JsonValue::Type::string;
            return string(value.text);
        }
        if (c == 't') return value.type = JsonValue::Type::boolean, value.boolean = true, literal("true");
        if (c == 'f') return value.type = JsonValue::Type::boolean, literal("false");
        if (c == 'n') return literal("null");
        return number(value);
    }

    std::string_view text_;
    std::size_t at_ = 0;
    std::string error_;
};

} // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    const auto it = object.find(std::string(key));
    return it == object.end() ? nullptr : &it->second;
}

std::optional<JsonValue> parseJson(std::string_view text, std::string& error) { return Reader(text).document(error); }

std::string jsonString(std::string_view text) {
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (c == '\n') quoted += "\\n";
        else quoted += c;
    }
    return quoted + "\"";
}

} // namespace rube::game
