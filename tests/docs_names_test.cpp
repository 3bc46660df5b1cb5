// The names docs/*.md write against the tree: every `kName` constant is
// defined in the code (outside a comment), and every path under src/,
// shaders_glsl/, tools/ or scenes/ is a file or folder of the repository, so
// a renamed constant or a moved file cannot leave its page behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "process.hpp"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = TIDEPOOL_SOURCE_DIR;

// Every docs/*.md page, by its name from the repository's root.
std::vector<std::pair<std::string, std::string>> docsPages() {
  std::vector<std::pair<std::string, std::string>> pages;
  for (const auto& entry : fs::directory_iterator(kSource / "docs")) {
    if (entry.path().extension() == ".md") {
      pages.emplace_back("docs/" + entry.path().filename().string(), readText(entry.path()));
    }
  }
  std::sort(pages.begin(), pages.end());
  return pages;
}

// C++ and GLSL text with its comments blanked out: a constant named only in a
// comment is not one the code has. (A scan, not a regex: libstdc++'s regex
// recurses per character and overflows the stack on a long comment.)
std::string withoutComments(const std::string& text) {
  std::string code;
  code.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      i = std::min(text.find('\n', i), text.size()) - 1;
    } else if (text.compare(i, 2, "/*") == 0) {
      i = std::min(text.find("*/", i + 2), text.size() - 2) + 1;
    } else {
      code += text[i];
      continue;
    }
    code += ' ';
  }
  return code;
}

// Every kName word of `text`: k, a capital, then letters, digits and _.
std::set<std::string> constantsIn(const std::string& text) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  std::set<std::string> names;
  for (size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] != 'k' || (i > 0 && word(text[i - 1])) || !std::isupper(static_cast<unsigned char>(text[i + 1])))
      continue;
    size_t end = i + 1;
    while (end < text.size() && word(text[end])) ++end;
    names.insert(text.substr(i, end - i));
    i = end;
  }
  return names;
}

// Every kName identifier the code of src/ and shaders_glsl/ writes.
std::set<std::string> constantsInCode() {
  std::set<std::string> names;
  for (const char* folder : {"src", "shaders_glsl"}) {
    for (const auto& entry : fs::recursive_directory_iterator(kSource / folder)) {
      if (!entry.is_regular_file()) continue;
      names.merge(constantsIn(withoutComments(readText(entry.path()))));
    }
  }
  return names;
}

}  // namespace

TEST(DocsNames, EveryConstantNamedIsInTheCode) {
  const std::set<std::string> code = constantsInCode();
  ASSERT_TRUE(code.contains("kSimulate")) << "no constants read from src/";
  size_t checked = 0;
  for (const auto& [page, text] : docsPages()) {
    for (const std::string& name : constantsIn(text)) {
      ++checked;
      EXPECT_TRUE(code.contains(name)) << page << " names " << name << ", which the code does not have";
    }
  }
  EXPECT_GT(checked, 10u);
}

TEST(DocsNames, EveryRepositoryPathNamedIsThere) {
  // A path starts a word and runs over letters, digits and _ . / -; a word in
  // capitals (src/NAME) is a placeholder, and a trailing "." ends a sentence.
  static const std::regex path(R"((^|[^A-Za-z0-9_./-])((src|shaders_glsl|tools|scenes)/[A-Za-z0-9_./-]*))");
  static const std::regex placeholder(R"(/[A-Z][A-Z_]*(/|$|\.))");
  size_t checked = 0;
  for (const auto& [page, text] : docsPages()) {
    for (std::sregex_iterator m(text.begin(), text.end(), path), end; m != end; ++m) {
      std::string named = (*m)[2].str();
      while (named.ends_with('.')) named.pop_back();
      if (std::regex_search(named, placeholder)) continue;
      ++checked;
      EXPECT_TRUE(fs::exists(kSource / named)) << page << " names " << named << ", which the repository does not have";
    }
  }
  EXPECT_GT(checked, 50u);
}

}  // namespace tp::test
