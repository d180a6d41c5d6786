#pragma once
// A JSON document written as it is produced: an object whose members are nlohmann values, and
// whose last member is an array of records streamed one by one (the cases of a sweep of millions
// need not be held in memory). The members are written by nlohmann::json, the records by it or
// by a typed writer that writes its bytes (json_record.hpp); nothing is spliced as free text.
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace mh {

/// Where an array of records written with element() stands in the stream: [begin, end) from its
/// first record's indentation to the last byte of its last record, and how many records it holds.
struct RecordSpan {
  std::uint64_t begin = 0, end = 0, count = 0;
};

class JsonObjectStream {
 public:
  /// Starts the object on `o`; `indent` is the indentation of its members (default 2 spaces: a
  /// document; larger: an object nested as an element of another stream's array, see element_open()).
  explicit JsonObjectStream(std::ostream& o, int indent = 2);
  /// A member `"key": value`, the value pretty-printed at the member's level.
  template <class T>
  void member(const std::string& key, const T& value) {
    if constexpr (std::is_same_v<T, nlohmann::ordered_json>) member_dumped(key, value.dump(2));
    else member_dumped(key, nlohmann::json(value).dump(2));
  }
  /// A member whose value is an array of records written with element() / element_json().
  void begin_array(const std::string& key);
  /// One record of the open array, already formatted as a JSON value (e.g. by format_case()).
  void element(const std::string& formatted_value);
  void element_json(const nlohmann::json& value);
  void element_json(const nlohmann::ordered_json& value);
  /// Starts an element of the open array that another JsonObjectStream (indent + 4) writes.
  void element_open();
  /// Text copied from a document this class wrote with the same indentation (mhcontact merge:
  /// no parse, no re-serialisation). member_verbatim: a member whose `value` is as it stood after
  /// `"key": ` (continuation lines already indented). elements_verbatim: records of the open
  /// array, `records` one or more of its records as they stood between the array's `[` + newline
  /// and its newline + `]` (the first record's indentation included); empty: nothing.
  void member_verbatim(const std::string& key, std::string_view value);
  void elements_verbatim(std::string_view records);
  void end_array();
  /// Closes the object (a document: and a final newline).
  void end();
  /// Append to `out` the RecordSpan of every array of this stream whose records are all written
  /// with element() (mhcontact merge then copies them by their byte range without reading them;
  /// a shard's shard.json lists them). The stream must tell its position (a file, not a pipe);
  /// where it cannot, no span is recorded.
  void record_spans(std::vector<RecordSpan>* out) { spans_ = out; }
  /// The underlying stream has not failed.
  bool good() const { return static_cast<bool>(o_); }

 private:
  std::ostream& o_;
  std::string pad_, close_pad_;
  bool first_member_ = true, first_element_ = true, in_array_ = false;
  std::vector<RecordSpan>* spans_ = nullptr;
  RecordSpan span_;
  bool span_open_ = false;  ///< the open array's records so far all written by element()
  void separator();
  void member_dumped(const std::string& key, const std::string& pretty);
};

}  // namespace mh
