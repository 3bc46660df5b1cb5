#pragma once
#include <optional>
#include <string>
#include <vector>

namespace tp::base {

// The candidate a mistyped `word` most likely meant: the nearest by edits
// (insert, delete, replace, swap two neighbours), if it is at most two edits
// away and fewer than half the word's letters; ties go to the first listed.
std::optional<std::string> closestWord(const std::string& word, const std::vector<std::string>& candidates);

// "a, b or c": candidates listed for a message.
std::string listWords(const std::vector<std::string>& words);

}  // namespace tp::base
