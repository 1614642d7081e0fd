#include "renderer/io/did_you_mean.h"

#include <algorithm>

namespace raylab {

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
    // Two edits catch a swapped pair of letters or a missing one, yet do not
    // suggest an unrelated short name.
    std::string best;
    size_t bestDistance = 3;
    for (const std::string& c : candidates) {
        const size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string name = closestName(word, candidates);
    return name.empty() ? "" : " (did you mean '" + name + "'?)";
}

}  // namespace raylab
