#include "scene_json.h"

#include <algorithm>
#include <string>
#include <vector>

#include "fooball/scene_error.h"
#include "message_text.h"

namespace fooball {
namespace {

using Json = nlohmann::json;

/// "line L, column C" (1-based; columns count bytes) of byte `offset` of `text`.
std::string lineAndColumn(std::string_view text, std::size_t offset) {
  const std::string_view before = text.substr(0, std::min(offset, text.size()));
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t lastNewline = before.rfind('\n');
  const std::size_t lineStart = lastNewline == std::string_view::npos ? 0 : lastNewline + 1;
  return "line " + std::to_string(line) + ", column " +
         std::to_string(before.size() - lineStart + 1);
}

[[noreturn]] void failAtPath(const std::string& path, std::string_view reason) {
  throw SceneError(path.empty() ? std::string(reason) : path + ": " + std::string(reason));
}

void checkNestingDepth(std::string_view text) {
  int depth = 0;
  bool inString = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        throw SceneError("invalid JSON at " + lineAndColumn(text, i) + ": nested more than " +
                         std::to_string(kMaxJsonDepth) + " levels deep");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

/// The REASON of nlohmann's "[json.exception.parse_error.101] parse error at line L, column C:
/// REASON", made printable: the line and column are recomputed from the byte offset.
std::string parseErrorReason(std::string_view what) {
  const std::size_t column = what.find("column ");
  const std::size_t colon = what.find(": ", column == std::string_view::npos ? 0 : column);
  return printableText(colon == std::string_view::npos ? what : what.substr(colon + 2), 200);
}

/// Follows the parser through the document: knows the path of the value being read, catches
/// repeated keys, and hands the streamed array's elements to the sink.
class DocumentTracker {
 public:
  DocumentTracker(std::string_view streamedKey, const JsonElementSink& sink)
      : streamedKey_(streamedKey), sink_(sink) {}

  /// nlohmann's parser callback; returning false drops the value from the document.
  bool onEvent(Json::parse_event_t event, const Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        startElement();
        push(event == Json::parse_event_t::array_start);
        return true;
      case Json::parse_event_t::key:
        noteKey(parsed.get_ref<const std::string&>());
        return true;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        --depth_;
        return !streamToSink(parsed);
      case Json::parse_event_t::value:
        startElement();
        return !streamToSink(parsed);
    }
    return true;
  }

  /// The path of the value the parser has not finished reading, e.g. "balls[3].radius".
  std::string pendingValuePath() const { return path(depth_, true); }

 private:
  struct Frame {
    bool isArray = false;
    std::size_t elementCount = 0;   ///< arrays: elements started so far
    std::string key;                ///< objects: the latest key
    std::vector<std::string> keys;  ///< objects: the keys seen so far
  };

  /// No object of the format has more than a dozen keys, so an object with more than this
  /// holds an unknown key and is rejected after parsing; tracking more would only cost time.
  static constexpr std::size_t kMaxTrackedKeys = 64;

  void push(bool isArray) {
    if (frames_.size() == depth_) frames_.emplace_back();
    Frame& frame = frames_[depth_++];
    frame.isArray = isArray;
    frame.elementCount = 0;
    frame.keys.clear();
  }

  void startElement() {
    if (depth_ > 0 && frames_[depth_ - 1].isArray) ++frames_[depth_ - 1].elementCount;
  }

  void noteKey(const std::string& key) {
    Frame& frame = frames_[depth_ - 1];
    if (std::find(frame.keys.begin(), frame.keys.end(), key) != frame.keys.end()) {
      failAtPath(path(depth_ - 1, false), "duplicate key " + quotedText(key));
    }
    if (frame.keys.size() < kMaxTrackedKeys) frame.keys.push_back(key);
    frame.key = key;
  }

  /// True when the value just completed is an element of the streamed array, now handed over.
  bool streamToSink(const Json& value) {
    const bool streamed =
        depth_ == 2 && !frames_[0].isArray && frames_[0].key == streamedKey_ && frames_[1].isArray;
    if (streamed) sink_(value, frames_[1].elementCount - 1);
    return streamed;
  }

  /// The path through the first `levels` open containers. Each array's element is the one
  /// being read, except that with `lastPending` the innermost array's next element has not
  /// started yet.
  std::string path(std::size_t levels, bool lastPending) const {
    std::string text;
    for (std::size_t level = 0; level < levels; ++level) {
      const Frame& frame = frames_[level];
      if (frame.isArray) {
        const bool pending = lastPending && level + 1 == levels;
        text += '[' + std::to_string(frame.elementCount - (pending ? 0 : 1)) + ']';
      } else {
        if (!text.empty()) text += '.';
        text += printableText(frame.key);
      }
    }
    return text;
  }

  std::string_view streamedKey_;
  const JsonElementSink& sink_;
  std::vector<Frame> frames_;  ///< reused as the parser enters and leaves containers
  std::size_t depth_ = 0;
};

}  // namespace

Json parseSceneJson(std::string_view text, std::string_view streamedKey,
                    const JsonElementSink& sink) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw SceneError("invalid JSON: the text is empty");
  }
  checkNestingDepth(text);
  DocumentTracker tracker(streamedKey, sink);
  try {
    return Json::parse(text.begin(), text.end(),
                       [&tracker](int, Json::parse_event_t event, Json& parsed) {
                         return tracker.onEvent(event, parsed);
                       });
  } catch (const Json::parse_error& error) {
    // `byte` counts the bytes read, the offending one included.
    const std::size_t offset = error.byte == 0 ? 0 : error.byte - 1;
    throw SceneError("invalid JSON at " + lineAndColumn(text, offset) + ": " +
                     parseErrorReason(error.what()));
  } catch (const Json::out_of_range& error) {
    // The parser raises only number overflow here: "... number overflow parsing '1e999'".
    const std::string_view what = error.what();
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    const std::string_view number =
        open < close ? what.substr(open + 1, close - open - 1) : std::string_view();
    failAtPath(tracker.pendingValuePath(),
               "the number " + printableText(number) + " is beyond the range of a double");
  }
}

}  // namespace fooball
