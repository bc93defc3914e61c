#include "core/internal/json_node.h"

#include <utility>
#include <vector>

namespace lucent {

Json parseStrictJson(const std::string& text, const std::string& name) {
    // The stack holds each open object's keys.
    std::vector<std::pair<std::string, std::set<std::string>>> open;
    std::string lastKey;
    const auto rejectDuplicateKeys = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) {
            open.emplace_back(lastKey, std::set<std::string>{});
        } else if (event == Json::parse_event_t::object_end) {
            if (!open.empty()) open.pop_back();
        } else if (event == Json::parse_event_t::key) {
            lastKey = parsed.get<std::string>();
            if (!open.empty() && !open.back().second.insert(lastKey).second) {
                std::string path;
                for (size_t i = 1; i < open.size(); ++i) path += "/" + open[i].first;
                throw Error(name, (path.empty() ? "/" : path) + ": duplicate key '" + lastKey +
                                      "' (JSON would silently keep the last one)");
            }
        }
        return true;
    };
    try {
        return Json::parse(text, rejectDuplicateKeys);
    } catch (const Json::exception& e) {
        throw Error(name, std::string("malformed JSON: ") + e.what());
    }
}

}  // namespace lucent
