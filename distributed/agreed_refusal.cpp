#include "distributed/detail/agreed_refusal.hpp"

#include <exception>
#include <new>
#include <string>

#include "core/error.hpp"

namespace coatfft {

namespace {

// What a rank's step ended with: nothing, a refusal of its input, or another failure.
enum class Outcome { done, invalid_argument, error };

}  // namespace

void agreed_refusal(const Communicator& comm, const std::function<void()>& step) {
  Outcome outcome = Outcome::done;
  std::string message;
  try {
    step();
  } catch (const InvalidArgument& e) {
    outcome = Outcome::invalid_argument;
    message = e.what();
  } catch (const std::bad_alloc&) {
    outcome = Outcome::invalid_argument;
    message = "out of memory (use fewer cells or --max-memory)";
  } catch (const std::exception& e) {
    outcome = Outcome::error;
    message = e.what();
  }
  // The first rank that refused speaks for all: its number is the smallest over the refusing ones.
  const int none = comm.size();
  const int first = -static_cast<int>(
      comm.max(-static_cast<double>(outcome == Outcome::done ? none : comm.rank())));
  if (first == none) return;
  // Its outcome travels as the message's first character.
  std::string first_message = comm.rank() == first
                                  ? std::string(1, char('0' + static_cast<int>(outcome))) + message
                                  : std::string();
  comm.broadcast(first_message, first);
  const bool unanimous = comm.all(outcome != Outcome::done && message == first_message.substr(1));
  const std::string text = unanimous
                               ? first_message.substr(1)
                               : detail::concat("rank ", first, ": ", first_message.substr(1));
  if (first_message[0] == char('0' + static_cast<int>(Outcome::invalid_argument)))
    throw InvalidArgument(text);
  throw Error(text);
}

}  // namespace coatfft
