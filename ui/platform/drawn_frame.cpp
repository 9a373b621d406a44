#include "ui/platform/drawn_frame.h"

#include <cstring>

#include "ui/platform/texture_generation.h"

namespace rockface::ui {

namespace {

template <class T>
void append(std::vector<unsigned char>& out, const T* data, std::size_t count) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  out.insert(out.end(), bytes, bytes + count * sizeof(T));
}

}  // namespace

void DrawnFrame::bytes_of(const ImDrawData& data, std::vector<unsigned char>& out) {
  out.clear();
  append(out, &data.DisplayPos, 1);
  append(out, &data.DisplaySize, 1);
  append(out, &data.FramebufferScale, 1);
  append(out, &data.CmdListsCount, 1);
  for (int n = 0; n < data.CmdListsCount; ++n) {
    const ImDrawList& list = *data.CmdLists[n];
    const int sizes[3] = {list.VtxBuffer.Size, list.IdxBuffer.Size, list.CmdBuffer.Size};
    append(out, sizes, 3);
    append(out, list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size));
    append(out, list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      // A user callback draws what the data does not say: never the same.
      const bool callback = cmd.UserCallback != nullptr;
      append(out, &callback, 1);
      append(out, &cmd.ClipRect, 1);
      append(out, &cmd.TextureId, 1);
      append(out, &cmd.VtxOffset, 1);
      append(out, &cmd.IdxOffset, 1);
      append(out, &cmd.ElemCount, 1);
    }
  }
}

bool DrawnFrame::same_as_last(const ImDrawData& data) {
  if (!valid_ || textures_ != texture_generation()) return false;
  for (int n = 0; n < data.CmdListsCount; ++n)
    for (const ImDrawCmd& cmd : data.CmdLists[n]->CmdBuffer)
      if (cmd.UserCallback) return false;
  bytes_of(data, scratch_);
  return scratch_.size() == last_.size() &&
         std::memcmp(scratch_.data(), last_.data(), last_.size()) == 0;
}

void DrawnFrame::remember(const ImDrawData& data) {
  bytes_of(data, last_);
  textures_ = texture_generation();
  valid_ = true;
}

}  // namespace rockface::ui
