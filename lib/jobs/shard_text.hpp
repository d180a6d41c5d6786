#pragma once
// A shard's output files as text, for `mhcontact merge`: read mapped (no copy of hundreds of MB
// into the process), copied on by the kernel where the pieces are large, and results.json split
// into its members by the layout JsonObjectStream (output/json_stream.hpp) writes, without
// parsing it.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "output/json_stream.hpp"

namespace mh {

class OutputFile;

/// The whole file `path` (InputError naming it when it cannot be read).
std::string read_all(const std::string& path);

/// A shard's file, read-only: mapped where the system has mmap (no copy, no zeroed buffer), else
/// read whole. `populate`: every page mapped at once (MAP_POPULATE) for a pass over the whole
/// text, instead of a page fault per 4 kB page. The file stays open, so that pieces of it can be
/// copied by the kernel (put_verbatim). `missing_rule`: the error's rule when it cannot be opened.
class ShardText {
 public:
  ShardText(const std::string& path, bool populate, const char* missing_rule);
  ~ShardText();
  ShardText(const ShardText&) = delete;
  ShardText& operator=(const ShardText&) = delete;
  std::string_view text() const { return text_; }
  /// The open file (-1: read whole, not mapped).
  int fd() const { return fd_; }
  /// The byte offset in the file of `part`, a view into text() (-1: the text is a copy).
  long long offset(std::string_view part) const {
    if (fd_ < 0 || part.data() < text_.data() || part.data() + part.size() > text_.data() + text_.size()) return -1;
    return static_cast<long long>(part.data() - text_.data());
  }

 private:
  int fd_ = -1;
  void* map_ = nullptr;
  std::size_t size_ = 0;
  std::string copy_;
  std::string_view text_;
};

/// `text`, a view into `src`, appended to `f`: a piece of 64 kB or more by a copy inside the
/// kernel (OutputFile::append_copy; through the process the bytes cost twice the CPU time: the
/// pages mapped in, then copied into the page cache), a smaller one or where the system cannot,
/// written.
void put_verbatim(OutputFile& f, const ShardText& src, std::string_view text);

// results.json's layout: an object's members stand one per line at its indentation `pad` (2 in
// the document, 6 in a batch's pair record), `"key": value`, the value's continuation lines
// indented deeper, its closing bracket at `pad`; a streamed array's records one per line at
// 2 × pad. JSON strings hold no raw newline, so a line of exactly `pad` spaces and a quote after
// a comma starts the next member, and a line of `pad` - 2 spaces and `}` closes the object.
struct JsonMember {
  std::string key;
  std::string_view value;  ///< as it stands after `"key": `
  std::size_t lines = 0;   ///< newlines in value (a streamed array: its records + 1)
};

/// What a shard's shard.json says of its results.json, written on `o` (its position: the
/// document's size), for the merge: {"bytes": size, "spans": [[begin, end, count], …]}, the spans
/// of its arrays of records (JsonObjectStream::record_spans). Null where `o` cannot tell its position.
nlohmann::json results_layout(std::ostream& o, const std::vector<RecordSpan>& spans);

/// The record arrays a merge copies by their byte range without reading them: split_members
/// jumps from a span's begin to its end (and counts its records as lines), in order.
struct SpanSkip {
  std::vector<RecordSpan> spans;
  std::size_t next = 0;
};

/// The SpanSkip of the shard.json member `layout` (results_layout) for the document `t`: checked
/// against its size (a document cut short or edited refused, naming `path`) and each span against
/// the text at its ends (a record starts a line, the array's newline follows the last).
SpanSkip span_skip(const nlohmann::json& layout, std::string_view t, const std::string& path);

/// Does `t` hold `s` at `p`?
inline bool text_at(std::string_view t, std::size_t p, std::string_view s) { return p <= t.size() && t.substr(p, s.size()) == s; }

/// Throws the InputError of a results.json not in the layout above (`path`, byte `at`).
[[noreturn]] void bad_results(const std::string& path, std::size_t at, const std::string& what);

/// The members of the object whose `{` is t[open]; returns the index just past its `}`. With
/// `stop_at` given, stops at the start of the member of that key (which is not split, nor the
/// members after it) and returns its index. One pass over the text: a memchr per line.
/// `skip`: record arrays jumped over (not read), their records counted from it.
std::size_t split_object(std::string_view t, std::size_t open, std::size_t pad, std::vector<JsonMember>* out, const std::string& path,
                         std::string_view stop_at = {}, SpanSkip* skip = nullptr);
/// The same from t[p], the newline before a member (or before the object's `}`).
std::size_t split_members(std::string_view t, std::size_t p, std::size_t pad, std::vector<JsonMember>* out, const std::string& path,
                          std::string_view stop_at = {}, SpanSkip* skip = nullptr);

/// The records of a streamed array member (`value` of a member at indentation `pad`) as
/// JsonObjectStream::elements_verbatim takes them; empty for `[]`.
std::string_view array_records(std::string_view value, std::size_t pad, const std::string& path, const std::string& key);

/// The member of key `key`, or nullptr.
const JsonMember* find_member(const std::vector<JsonMember>& ms, const std::string& key);

/// A member `key` whose value is `value`, a view into `src`, copied as it stands (a large value
/// by put_verbatim; the stream writes the separator, the key and the value's first byte).
void member_copied(JsonObjectStream& w, OutputFile& f, const ShardText& src, const std::string& key, std::string_view value);

/// Records of the open array of `w` as JsonObjectStream::elements_verbatim takes them, `records`
/// a view into `src` (the stream writes the separator and the first byte, the rest put_verbatim).
void elements_copied(JsonObjectStream& w, OutputFile& f, const ShardText& src, std::string_view records);

}  // namespace mh
