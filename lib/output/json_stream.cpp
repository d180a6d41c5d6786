#include "output/json_stream.hpp"

namespace mh {

namespace {
// Indent the continuation lines of a pretty-printed value by `pad`.
std::string indented(const std::string& s, const std::string& pad) {
  std::string out;
  out.reserve(s.size() + s.size() / 8);
  for (char c : s) {
    out += c;
    if (c == '\n') out += pad;
  }
  return out;
}
}  // namespace

JsonObjectStream::JsonObjectStream(std::ostream& o, int indent)
    : o_(o), pad_(static_cast<std::size_t>(indent), ' '), close_pad_(static_cast<std::size_t>(indent > 2 ? indent - 2 : 0), ' ') {
  o_ << "{";
}

void JsonObjectStream::separator() {
  o_ << (first_member_ ? "\n" : ",\n") << pad_;
  first_member_ = false;
}

void JsonObjectStream::member_dumped(const std::string& key, const std::string& pretty) {
  separator();
  o_ << nlohmann::json(key).dump() << ": " << indented(pretty, pad_);
}

void JsonObjectStream::begin_array(const std::string& key) {
  separator();
  o_ << nlohmann::json(key).dump() << ": [";
  in_array_ = true;
  first_element_ = true;
  span_open_ = false;
}

void JsonObjectStream::element(const std::string& formatted_value) {
  if (first_element_) {
    o_ << "\n";
    if (spans_) {
      const auto at = o_.tellp();
      span_open_ = at >= 0;
      span_ = {static_cast<std::uint64_t>(at >= 0 ? static_cast<std::streamoff>(at) : 0), 0, 0};
    }
  } else {
    o_ << ",\n";
  }
  o_ << pad_ << pad_ << formatted_value;
  first_element_ = false;
  ++span_.count;
}

void JsonObjectStream::element_json(const nlohmann::json& value) { element(value.dump()); }
void JsonObjectStream::element_json(const nlohmann::ordered_json& value) { element(value.dump()); }

void JsonObjectStream::element_open() {
  span_open_ = false;
  o_ << (first_element_ ? "\n" : ",\n") << pad_ << pad_;
  first_element_ = false;
}

void JsonObjectStream::member_verbatim(const std::string& key, std::string_view value) {
  separator();
  o_ << nlohmann::json(key).dump() << ": " << value;
}

void JsonObjectStream::elements_verbatim(std::string_view records) {
  if (records.empty()) return;
  span_open_ = false;
  o_ << (first_element_ ? "\n" : ",\n") << records;
  first_element_ = false;
}

void JsonObjectStream::end_array() {
  if (span_open_ && spans_) {
    const auto at = o_.tellp();
    if (at >= 0) {
      span_.end = static_cast<std::uint64_t>(static_cast<std::streamoff>(at));
      spans_->push_back(span_);
    }
  }
  span_open_ = false;
  if (!first_element_) o_ << "\n" << pad_;
  o_ << "]";
  in_array_ = false;
}

void JsonObjectStream::end() {
  o_ << "\n" << close_pad_ << "}";
  if (close_pad_.empty()) o_ << "\n";
}

}  // namespace mh
