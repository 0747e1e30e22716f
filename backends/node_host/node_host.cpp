#include "node_host.h"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "host_files.h"

namespace fooball::node_host {

namespace {

/// The child's stderr tail as one line: its lines joined by " | ", without a JavaScript stack's
/// "    at …" frames (the error's own lines say what went wrong), the last ~600 characters.
std::string quoteTail(const std::string& tail) {
  constexpr std::size_t kQuoted = 600;
  std::string joined;
  std::size_t start = 0;
  while (start < tail.size()) {
    std::size_t end = tail.find('\n', start);
    if (end == std::string::npos) end = tail.size();
    std::string_view line(tail.data() + start, end - start);
    start = end + 1;
    while (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    const std::size_t text = line.find_first_not_of(" \t");
    if (text == std::string_view::npos) continue;
    if (text > 0 && line.substr(text).starts_with("at ")) continue;
    if (!joined.empty()) joined += " | ";
    joined += line;
  }
  if (joined.size() > kQuoted) joined = "…" + joined.substr(joined.size() - kQuoted);
  return joined.empty() ? "its stderr is empty" : "its stderr ends: " + joined;
}

/// node, the words of $FOOBALL_NODE_OPTIONS (node's and V8's own flags, split at spaces: also
/// those NODE_OPTIONS refuses, such as --liftoff-only), and the host's script.
std::vector<std::string> hostCommand(const std::string& hostScript) {
  const auto node = nodeProgram();
  // posix_spawnp looks for "node" on PATH itself; the resolved path only makes errors exact.
  std::vector<std::string> command{node ? node->string() : std::string("node")};
  if (const char* options = std::getenv("FOOBALL_NODE_OPTIONS"); options != nullptr) {
    std::istringstream words(options);
    for (std::string word; words >> word;)
      command.push_back(word);
  }
  command.push_back(hostScript);
  return command;
}

int majorVersion(std::string_view version) {
  int major = 0;
  std::from_chars(version.data(), version.data() + version.size(), major);
  return major;
}

}  // namespace

NodeHost::NodeHost(std::string engine, const std::string& hostScript,
                   std::chrono::milliseconds timeout)
    : engine_(std::move(engine)), timeout_(timeout), child_(hostCommand(hostScript)) {
  writer_.begin(FrameKind::Hello);
  writer_.u32Pair(kProtocolVersion, 0);
  writer_.string(engine_);
  writer_.end();
  if (exchange() != FrameKind::Ready) {
    child_.markGarbage();
    fail("answered the handshake with something else");
  }
  FrameReader reader(reply_);
  const std::uint32_t protocol = reader.u32();
  reader.u32();
  nodeVersion_ = reader.string();
  engineVersion_ = reader.string();
  if (!reader.ok()) {
    child_.markGarbage();
    fail("answered a malformed handshake");
  }
  if (protocol != kProtocolVersion) {
    fail("speaks protocol " + std::to_string(protocol) + ", this program " +
         std::to_string(kProtocolVersion) + " (the host's files are from another version)");
  }
  if (majorVersion(nodeVersion_) < 18) {
    fail("runs Node.js " + nodeVersion_ + ", and needs 18 or later (fix: apt install nodejs)");
  }
}

void NodeHost::fail(const std::string& what) {
  std::string why = what;
  if (child_.fault() != ChildFault::None || why.empty()) why = child_.failure(timeout_);
  child_.failure(timeout_);  // kills and reaps, if it still runs
  throw HostError(engine_ + ": the Node.js host " + why + "; " + quoteTail(child_.stderrTail()));
}

FrameKind NodeHost::exchange() {
  const auto deadline = ChildProcess::Clock::now() + timeout_;
  if (!child_.write(writer_.bytes(), deadline)) fail({});
  std::byte header[kHeaderBytes];
  if (!child_.read(header, deadline)) fail({});
  std::uint32_t bytes = 0;
  std::uint32_t kind = 0;
  std::memcpy(&bytes, header, 4);
  std::memcpy(&kind, header + 4, 4);
  const bool known = kind == static_cast<std::uint32_t>(FrameKind::Ready) ||
                     kind == static_cast<std::uint32_t>(FrameKind::State) ||
                     kind == static_cast<std::uint32_t>(FrameKind::Error);
  if (!known || bytes > kMaxReplyBytes || bytes % 8 != 0) {
    child_.markGarbage();
    fail({});
  }
  reply_.resize(bytes);
  if (!child_.read(reply_, deadline)) fail({});
  if (kind == static_cast<std::uint32_t>(FrameKind::Error)) {
    FrameReader reader(reply_);
    const std::string message(reader.string());
    fail("reported an error: " + message);
  }
  return static_cast<FrameKind>(kind);
}

void NodeHost::exchangeForState() {
  if (exchange() != FrameKind::State) {
    child_.markGarbage();
    fail({});
  }
  FrameReader reader(reply_);
  const std::uint32_t balls = reader.u32();
  reader.u32();
  counters_.ballCollisions = reader.f64();
  counters_.wallCollisions = reader.f64();
  counters_.wallImpulse = reader.f64();
  counters_.dragLoss = reader.f64();
  counters_.engineSteps = reader.f64();
  counters_.ballsBroughtBack = reader.f64();
  counters_.stepSeconds = reader.f64();
  if (!reader.ok() || reply_.size() != kStateHeadBytes + 32 * std::size_t{balls}) {
    child_.markGarbage();
    fail({});
  }
  state_.resize(4 * std::size_t{balls});
  // No balls: an empty vector's data() may be null, which memcpy must not be given.
  if (!state_.empty())
    std::memcpy(state_.data(), reply_.data() + kStateHeadBytes, state_.size() * sizeof(double));
}

void NodeHost::setOptions(const OptionSet& options) {
  writer_.begin(FrameKind::Options);
  writer_.u32Pair(static_cast<std::uint32_t>(options.specs().size()), 0);
  for (const OptionSpec& spec : options.specs()) {
    writer_.string(spec.name);
    writer_.f64(options.value(spec.name));
  }
  writer_.end();
  exchangeForState();
}

void NodeHost::load(const Scene& scene) {
  writer_.begin(FrameKind::Load);
  writer_.f64(scene.box.width);
  writer_.f64(scene.box.height);
  writer_.world(scene.world);
  writer_.u32Pair(static_cast<std::uint32_t>(scene.balls.size()), 0);
  for (const BallDef& ball : scene.balls)
    writer_.ball(ball);
  writer_.end();
  exchangeForState();
}

void NodeHost::setWorld(const WorldSettings& world) {
  writer_.begin(FrameKind::World);
  writer_.world(world);
  writer_.end();
  exchangeForState();
}

void NodeHost::setBall(std::size_t index, const BallDef& ball) {
  writer_.begin(FrameKind::SetBall);
  writer_.u32Pair(static_cast<std::uint32_t>(index), 0);
  writer_.ball(ball);
  writer_.end();
  exchangeForState();
}

void NodeHost::step(double dt, std::span<const Vec2> forces) {
  const auto start = ChildProcess::Clock::now();
  writer_.begin(FrameKind::Step);
  writer_.f64(dt);
  writer_.u32Pair(static_cast<std::uint32_t>(forces.size()), 0);
  static_assert(sizeof(Vec2) == 2 * sizeof(double));  // fx, fy as the frame has them
  writer_.raw(std::as_bytes(forces));
  writer_.end();
  exchangeForState();
  stepSeconds_ += std::chrono::duration<double>(ChildProcess::Clock::now() - start).count();
}

}  // namespace fooball::node_host
