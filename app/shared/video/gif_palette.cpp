#include "gif_palette.h"

#include <algorithm>
#include <vector>

namespace fooball::video {

namespace {

constexpr std::size_t kAdaptiveEntries = 192;  // from the first frame; the rest: the cube
constexpr int kCubeLevels = 4;                 // 4³ = 64 = 256 − 192

int binOf(int r, int g, int b) {
  return ((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3);
}

/// The pixels of one 5-bit-a-channel bin of the first frame: how many, and their mean colour.
struct BinColour {
  double channel[3];  ///< mean R, G, B, 0…255
  double weight;      ///< pixels
};

/// Median cut: a box of bins, split at the weighted median of its widest channel.
struct Box {
  std::size_t begin;
  std::size_t end;
  double widest() const { return range; }
  int axis = 0;
  double range = 0.0;
};

void measure(Box& box, const std::vector<BinColour>& bins) {
  double low[3] = {255.0, 255.0, 255.0};
  double high[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = box.begin; i < box.end; ++i) {
    for (int c = 0; c < 3; ++c) {
      low[c] = std::min(low[c], bins[i].channel[c]);
      high[c] = std::max(high[c], bins[i].channel[c]);
    }
  }
  box.axis = 0;
  box.range = -1.0;
  for (int c = 0; c < 3; ++c) {
    if (high[c] - low[c] > box.range) {
      box.range = high[c] - low[c];
      box.axis = c;
    }
  }
}

std::uint32_t argb(double r, double g, double b) {
  const auto byte = [](double v) {
    return static_cast<std::uint32_t>(std::clamp(v + 0.5, 0.0, 255.0));
  };
  return 0xFF000000u | (byte(r) << 16) | (byte(g) << 8) | byte(b);
}

}  // namespace

GifPalette::GifPalette(const RgbFrame& firstFrame) {
  // Every bin's pixel count and colour sums.
  std::vector<double> sums(kBins * 3, 0.0);
  std::vector<double> counts(kBins, 0.0);
  for (int y = 0; y < firstFrame.height; ++y) {
    const std::uint8_t* row = firstFrame.pixels + y * firstFrame.bytesPerLine;
    for (int x = 0; x < firstFrame.width; ++x) {
      const int r = row[3 * x];
      const int g = row[3 * x + 1];
      const int b = row[3 * x + 2];
      const int bin = binOf(r, g, b);
      counts[bin] += 1.0;
      sums[3 * bin] += r;
      sums[3 * bin + 1] += g;
      sums[3 * bin + 2] += b;
    }
  }
  std::vector<BinColour> bins;
  for (std::size_t bin = 0; bin < kBins; ++bin) {
    if (counts[bin] == 0.0) continue;
    bins.push_back({{sums[3 * bin] / counts[bin], sums[3 * bin + 1] / counts[bin],
                     sums[3 * bin + 2] / counts[bin]},
                    counts[bin]});
  }

  // Split the box of the widest colour range (among those of more than one bin) until there
  // are enough boxes, or none can split.
  std::vector<Box> boxes;
  if (!bins.empty()) {
    boxes.push_back({0, bins.size()});
    measure(boxes.back(), bins);
  }
  while (boxes.size() < kAdaptiveEntries) {
    auto widest = boxes.end();
    for (auto box = boxes.begin(); box != boxes.end(); ++box) {
      if (box->end - box->begin < 2 || box->range <= 0.0) continue;
      if (widest == boxes.end() || box->widest() > widest->widest()) widest = box;
    }
    if (widest == boxes.end()) break;
    const int axis = widest->axis;
    const auto first = bins.begin() + std::ptrdiff_t(widest->begin);
    const auto last = bins.begin() + std::ptrdiff_t(widest->end);
    std::sort(first, last, [axis](const BinColour& a, const BinColour& b) {
      return a.channel[axis] < b.channel[axis];
    });
    double total = 0.0;
    for (auto bin = first; bin != last; ++bin)
      total += bin->weight;
    // The weighted median, but never an empty half.
    double below = 0.0;
    std::size_t split = widest->begin + 1;
    for (std::size_t i = widest->begin; i + 1 < widest->end; ++i) {
      below += bins[i].weight;
      split = i + 1;
      if (below >= total / 2.0) break;
    }
    Box upper{split, widest->end};
    widest->end = split;
    measure(*widest, bins);
    measure(upper, bins);
    boxes.push_back(upper);
  }

  for (const Box& box : boxes) {
    double weight = 0.0;
    double channel[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = box.begin; i < box.end; ++i) {
      weight += bins[i].weight;
      for (int c = 0; c < 3; ++c)
        channel[c] += bins[i].channel[c] * bins[i].weight;
    }
    colours_[count_++] = argb(channel[0] / weight, channel[1] / weight, channel[2] / weight);
  }
  constexpr double kStep = 255.0 / (kCubeLevels - 1);
  for (int r = 0; r < kCubeLevels; ++r) {
    for (int g = 0; g < kCubeLevels; ++g) {
      for (int b = 0; b < kCubeLevels; ++b)
        colours_[count_++] = argb(r * kStep, g * kStep, b * kStep);
    }
  }
  // Unused entries (a first frame of few colours) repeat black, never chosen before it.
  for (std::size_t i = count_; i < kSize; ++i)
    colours_[i] = 0xFF000000u;
  lookup_.fill(kUnknown);
}

std::uint8_t GifPalette::nearest(int r, int g, int b) const {
  // Weighted as the eye weighs the channels (green most, blue least), enough to pick among
  // nearby entries.
  std::size_t best = 0;
  long bestDistance = -1;
  for (std::size_t i = 0; i < count_; ++i) {
    const long dr = long((colours_[i] >> 16) & 0xFF) - r;
    const long dg = long((colours_[i] >> 8) & 0xFF) - g;
    const long db = long(colours_[i] & 0xFF) - b;
    const long distance = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
    if (bestDistance < 0 || distance < bestDistance) {
      bestDistance = distance;
      best = i;
    }
  }
  return static_cast<std::uint8_t>(best);
}

std::uint8_t GifPalette::indexOf(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const int bin = binOf(r, g, b);
  if (lookup_[std::size_t(bin)] == kUnknown) {
    // The bin's centre stands for all its colours.
    lookup_[std::size_t(bin)] =
        nearest(((r >> 3) << 3) | 4, ((g >> 3) << 3) | 4, ((b >> 3) << 3) | 4);
  }
  return static_cast<std::uint8_t>(lookup_[std::size_t(bin)]);
}

void GifPalette::map(const RgbFrame& frame, std::uint8_t* indices, std::ptrdiff_t bytesPerLine) {
  for (int y = 0; y < frame.height; ++y) {
    const std::uint8_t* row = frame.pixels + y * frame.bytesPerLine;
    std::uint8_t* out = indices + y * bytesPerLine;
    for (int x = 0; x < frame.width; ++x)
      out[x] = indexOf(row[3 * x], row[3 * x + 1], row[3 * x + 2]);
  }
}

}  // namespace fooball::video
