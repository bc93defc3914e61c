#pragma once
// A value built the first time it is asked for, once, from whichever thread asks
// first; the owner stays movable. For what only some commands need: ss with
// --light sh never casts a ray into the mesh it draws.
#include <memory>
#include <mutex>
#include <optional>

namespace lucent {

template <class T>
class Lazy {
public:
    // make() returns the T; an exception leaves it unbuilt for the next call.
    template <class Make>
    const T& get(Make&& make) const {
        std::call_once(state_->once, [&] { state_->value.emplace(make()); });
        return *state_->value;
    }

private:
    struct State {
        std::once_flag once;
        std::optional<T> value;
    };
    std::unique_ptr<State> state_ = std::make_unique<State>();
};

}  // namespace lucent
