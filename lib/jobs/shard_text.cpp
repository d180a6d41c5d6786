#include "jobs/shard_text.hpp"

#include <algorithm>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "output/json_stream.hpp"
#include "output/output_file.hpp"

namespace mh {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read (is this the output directory of a `run --shard`?)");
  in.seekg(0, std::ios::end);
  std::string text(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)), '\0');
  in.seekg(0);
  if (!in.read(text.data(), static_cast<std::streamsize>(text.size()))) throw InputError(path, "", "cannot read it to its end");
  return text;
}

ShardText::ShardText(const std::string& path, bool populate, const char* missing_rule) {
#if defined(__unix__) || defined(__APPLE__)
  fd_ = ::open(path.c_str(), O_RDONLY);
  if (fd_ < 0) throw InputError(path, "", missing_rule);
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && st.st_size > 0) {
    size_ = static_cast<std::size_t>(st.st_size);
    int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
    if (populate) flags |= MAP_POPULATE;
#endif
    void* p = ::mmap(nullptr, size_, PROT_READ, flags, fd_, 0);
    if (p != MAP_FAILED) map_ = p;
  }
  if (map_) {
    text_ = std::string_view(static_cast<const char*>(map_), size_);
    return;
  }
  ::close(fd_);
  fd_ = -1;
#endif
  (void)populate;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", missing_rule);
  copy_ = read_all(path);
  text_ = copy_;
}

ShardText::~ShardText() {
#if defined(__unix__) || defined(__APPLE__)
  if (map_) ::munmap(map_, size_);
  if (fd_ >= 0) ::close(fd_);
#endif
}

void put_verbatim(OutputFile& f, const ShardText& src, std::string_view text) {
  constexpr std::size_t kMinCopy = std::size_t{1} << 16;
  const long long at = src.offset(text);
  if (text.size() >= kMinCopy && at >= 0 && f.append_copy(src.fd(), at, text.size())) return;
  f.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
}

[[noreturn]] void bad_results(const std::string& path, std::size_t at, const std::string& what) {
  throw InputError(path, "at byte " + std::to_string(at), "not a results.json as mhcontact run writes it: " + what,
                   "give the shard directories as `run --shard` wrote them (re-run that shard)");
}

nlohmann::json results_layout(std::ostream& o, const std::vector<RecordSpan>& spans) {
  const auto size = o.tellp();
  if (size < 0) return nullptr;
  nlohmann::json s = nlohmann::json::array();
  for (const auto& r : spans) s.push_back({r.begin, r.end, r.count});
  return {{"bytes", static_cast<std::uint64_t>(static_cast<std::streamoff>(size))}, {"spans", s}};
}

SpanSkip span_skip(const nlohmann::json& layout, std::string_view t, const std::string& path) {
  SpanSkip skip;
  if (!layout.is_object()) return skip;  // none recorded: the records are read line by line
  const auto bytes = layout.find("bytes");
  if (bytes == layout.end() || !bytes->is_number_unsigned()) bad_results(path, 0, "its shard.json's \"results_json\" has no size");
  if (bytes->get<std::uint64_t>() != t.size())
    bad_results(path, std::min<std::size_t>(t.size(), bytes->get<std::uint64_t>()),
                std::to_string(t.size()) + " bytes, its shard.json says " + bytes->dump() + " (cut short or edited)");
  const auto spans = layout.find("spans");
  if (spans == layout.end() || !spans->is_array()) bad_results(path, 0, "its shard.json's \"results_json\" has no \"spans\"");
  std::uint64_t past = 0;
  for (const auto& s : *spans) {
    if (!s.is_array() || s.size() != 3 || !s[0].is_number_unsigned() || !s[1].is_number_unsigned() || !s[2].is_number_unsigned())
      bad_results(path, 0, "its shard.json's record span " + s.dump() + " is not [begin, end, count]");
    const RecordSpan r{s[0].get<std::uint64_t>(), s[1].get<std::uint64_t>(), s[2].get<std::uint64_t>()};
    if (r.begin <= past || r.end < r.begin || r.end >= t.size() || r.count == 0 || t[r.begin - 1] != '\n' || t[r.end] != '\n' ||
        t[r.begin] != ' ')
      bad_results(path, r.begin, "its shard.json's record span " + s.dump() + " is not an array's records in the document");
    skip.spans.push_back(r);
    past = r.end;
  }
  return skip;
}

std::size_t split_members(std::string_view t, std::size_t p, std::size_t pad, std::vector<JsonMember>* out, const std::string& path,
                          std::string_view stop_at, SpanSkip* skip) {
  const std::string lead = "\n" + std::string(pad, ' '), close = "\n" + std::string(pad - 2, ' ') + "}";
  if (text_at(t, p, close)) return p + close.size();
  for (;;) {
    if (!text_at(t, p, lead + "\"")) bad_results(path, p, "a member expected at indentation " + std::to_string(pad));
    const std::size_t k = p + lead.size() + 1, ke = t.find('"', k);
    if (ke == std::string_view::npos || !text_at(t, ke + 1, ": ")) bad_results(path, k, "a member's key expected");
    std::string key(t.substr(k, ke - k));
    if (!stop_at.empty() && key == stop_at) return p;
    const std::size_t v = ke + 3;
    for (std::size_t q = v, lines = 0;; ++q, ++lines) {
      if (skip && skip->next < skip->spans.size() && skip->spans[skip->next].begin <= q) {
        // A record array the shard's shard.json spans: jumped over, its records counted.
        const RecordSpan& r = skip->spans[skip->next++];
        if (r.begin != q) bad_results(path, r.begin, "its shard.json's record span does not start at a line of the member \"" + key + "\"");
        q = r.end;
        lines += r.count - 1;
      }
      q = t.find('\n', q);
      if (q == std::string_view::npos) bad_results(path, v, "the document ends inside the member \"" + key + "\"");
      if (t[q - 1] == ',' && text_at(t, q, lead + "\"")) {
        out->push_back({std::move(key), t.substr(v, q - 1 - v), lines});
        p = q;
        break;
      }
      if (text_at(t, q, close)) {
        out->push_back({std::move(key), t.substr(v, q - v), lines});
        return q + close.size();
      }
    }
  }
}

std::size_t split_object(std::string_view t, std::size_t open, std::size_t pad, std::vector<JsonMember>* out, const std::string& path,
                         std::string_view stop_at, SpanSkip* skip) {
  if (open >= t.size() || t[open] != '{') bad_results(path, open, "an object expected");
  return split_members(t, open + 1, pad, out, path, stop_at, skip);
}

void member_copied(JsonObjectStream& w, OutputFile& f, const ShardText& src, const std::string& key, std::string_view value) {
  if (value.size() < 2) return w.member_verbatim(key, value);
  w.member_verbatim(key, value.substr(0, 1));
  put_verbatim(f, src, value.substr(1));
}

void elements_copied(JsonObjectStream& w, OutputFile& f, const ShardText& src, std::string_view records) {
  if (records.empty()) return;
  w.elements_verbatim(records.substr(0, 1));
  put_verbatim(f, src, records.substr(1));
}

std::string_view array_records(std::string_view value, std::size_t pad, const std::string& path, const std::string& key) {
  if (value == "[]") return {};
  const std::string tail = "\n" + std::string(pad, ' ') + "]";
  if (value.size() < 2 + tail.size() || value.substr(0, 2) != "[\n" || value.substr(value.size() - tail.size()) != tail)
    bad_results(path, 0, "\"" + key + "\" is not an array of records");
  return value.substr(2, value.size() - 2 - tail.size());
}

const JsonMember* find_member(const std::vector<JsonMember>& ms, const std::string& key) {
  for (const auto& m : ms)
    if (m.key == key) return &m;
  return nullptr;
}

}  // namespace mh
