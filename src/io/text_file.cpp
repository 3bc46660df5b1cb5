#include "io/text_file.hpp"

#include <memory>
#include <stdexcept>

namespace tp::io {

void writeTemporary(const base::AtomicFile& file, const std::function<void(std::FILE*)>& body) {
  const auto close = [](std::FILE* f) { std::fclose(f); };
  std::unique_ptr<std::FILE, decltype(close)> f(std::fopen(file.tempPath().c_str(), "w"), close);
  if (!f) throw std::runtime_error("cannot write " + file.target());
  body(f.get());
  if (std::fflush(f.get()) != 0 || std::ferror(f.get()))
    throw std::runtime_error("cannot write " + file.target() + ": disk full?");
}

}  // namespace tp::io
