// The serial link under the host protocols: lines, replies, command tables, attaching.
#include <gtest/gtest.h>

#include <string>

#include "stepdance/interfaces/link/command_table.hpp"
#include "stepdance/interfaces/link/line_reader.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"
#include "stepdance/interfaces/link/serial_link.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance::link {
namespace {

using test_support::FakeByteStream;

constexpr LineRules kEbbRules{/*cr_ends_line=*/true, /*strip_trailing_cr=*/false, /*skip_empty_lines=*/true,
                              /*printable_only=*/true};
constexpr LineRules kRpcRules{/*cr_ends_line=*/false, /*strip_trailing_cr=*/true, /*skip_empty_lines=*/true,
                              /*printable_only=*/false};

// Every line the reader hands over, "!" marking an overflowed one.
template <size_t N>
std::string all_lines(LineReader<N>& reader, FakeByteStream& stream) {
  std::string out;
  while (reader.pump(stream)) {
    out += reader.overflowed() ? "!" : "";
    out += std::string(reader.text(), reader.length()) + "|";
    reader.take();
  }
  return out;
}

TEST(LineReaderTest, CrOrLfEndsALineAndPairsAndEmptyLinesAreSkipped) {
  LineReader<16> reader(kEbbRules);
  FakeByteStream stream;
  stream.send("V\r\nQP\n\rSM,10,1,1\r\r\n\nXX");
  EXPECT_EQ(all_lines(reader, stream), "V|QP|SM,10,1,1|");
  stream.send("\n");
  EXPECT_EQ(all_lines(reader, stream), "XX|");  // the unfinished line waited for its end
}

TEST(LineReaderTest, PrintableOnlyLeavesControlAndHighBytesOut) {
  LineReader<16> reader(kEbbRules);
  FakeByteStream stream;
  stream.send(std::string("Q\x01P\x7F\xFF\t\r", 8));
  EXPECT_EQ(all_lines(reader, stream), "QP|");
}

TEST(LineReaderTest, LfOnlyRulesKeepCrInsideAndStripItBeforeTheLf) {
  LineReader<16> reader(kRpcRules);
  FakeByteStream stream;
  stream.send("a\rb\r\n\r\n\nc\n");
  EXPECT_EQ(all_lines(reader, stream), "a\rb|c|");  // "\r\n" alone is an empty line: skipped
}

TEST(LineReaderTest, AnOverlongLineIsConsumedWholeCutAndFlagged) {
  LineReader<4> reader(kRpcRules);
  FakeByteStream stream;
  stream.send("abcd\nabcde\nxy\n");
  EXPECT_EQ(all_lines(reader, stream), "abcd|!abcd|xy|");
  EXPECT_EQ(reader.overflows(), 1u);
  EXPECT_EQ(reader.capacity(), 4u);
}

TEST(LineReaderTest, ACrBeyondCapacityOverflowsWhenCrIsData) {
  // With LF-only rules the CR is a byte of the line: 4 bytes and a CR do not fit in 4.
  LineReader<4> reader(kRpcRules);
  FakeByteStream stream;
  stream.send("abcd\r\n");
  EXPECT_EQ(all_lines(reader, stream), "!abcd|");
}

TEST(LineReaderTest, AWaitingLineStopsReadingUntilTaken) {
  LineReader<16> reader(kEbbRules);
  FakeByteStream stream;
  stream.send("A\rB\rC\r");
  ASSERT_TRUE(reader.pump(stream));
  EXPECT_STREQ(reader.text(), "A");
  EXPECT_EQ(stream.to_board.size(), 4u);  // "B\rC\r" stays in the stream: back-pressure
  ASSERT_TRUE(reader.pump(stream));       // pumping again reads nothing while A waits
  EXPECT_EQ(stream.to_board.size(), 4u);
  EXPECT_FALSE(reader.feed('Z'));  // nor does feeding
  EXPECT_STREQ(reader.text(), "A");
  reader.take();
  ASSERT_TRUE(reader.pump(stream));
  EXPECT_STREQ(reader.text(), "B");
}

TEST(LineReaderTest, ClearForgetsThePartialLine) {
  LineReader<16> reader(kEbbRules);
  FakeByteStream stream;
  stream.send("abc");
  EXPECT_FALSE(reader.pump(stream));
  reader.clear();
  stream.send("d\r");
  ASSERT_TRUE(reader.pump(stream));
  EXPECT_STREQ(reader.text(), "d");
}

TEST(ReplyRingTest, QueuesWholeTextsAndFlushesAsTheHostReads) {
  ReplyRing<8> ring;
  FakeByteStream stream;
  stream.write_room = 3;
  char storage[8];
  TextWriter line(storage, sizeof(storage));
  line.text("OK");
  EXPECT_TRUE(ring.reserve(8));
  EXPECT_TRUE(ring.send_line(line));  // 4 bytes
  EXPECT_TRUE(ring.send("abc"));      // 7 bytes
  EXPECT_FALSE(ring.reserve(2));
  EXPECT_FALSE(ring.send("de"));  // refused whole, counted
  EXPECT_EQ(ring.dropped(), 1u);
  EXPECT_EQ(ring.flush(stream), 3u);
  EXPECT_EQ(stream.take(), "OK\r");
  stream.write_room = 100;
  EXPECT_TRUE(ring.send_line(line, "\n"));  // wraps around the end of the storage
  EXPECT_EQ(ring.flush(stream), 7u);
  EXPECT_EQ(stream.take(), "\nabcOK\n");
  EXPECT_EQ(ring.pending(), 0u);
  EXPECT_EQ(ring.space(), 8u);
}

TEST(ReplyRingTest, ATextThatWrapsGoesInWholeAndARefusalLeavesTheQueueAsItWas) {
  ReplyRing<8> ring;
  FakeByteStream stream;
  stream.write_room = 4;
  EXPECT_TRUE(ring.send("abcdef"));
  EXPECT_EQ(ring.flush(stream), 4u);  // "ef" stays, from the middle of the storage
  EXPECT_TRUE(ring.send("ghijkl"));   // 6 bytes: to the end of the storage and on from its start
  EXPECT_FALSE(ring.send("x"));       // full: refused and counted
  char storage[4];
  TextWriter empty(storage, sizeof(storage));
  EXPECT_FALSE(ring.send_line(empty));  // even an empty line needs room for its CR LF
  EXPECT_EQ(ring.dropped(), 2u);
  stream.write_room = 100;
  EXPECT_EQ(ring.flush(stream), 8u);
  EXPECT_EQ(stream.take(), "abcdefghijkl");
  EXPECT_TRUE(ring.send("mnopqrs"));  // 7 of 8 bytes fit ...
  EXPECT_FALSE(ring.send("tu"));      // ... and a text that would run out half way is refused whole
  EXPECT_EQ(ring.flush(stream), 7u);
  EXPECT_EQ(stream.take(), "mnopqrs");
}

TEST(ReplyRingTest, AHostThatReadsNothingLosesNothing) {
  ReplyRing<16> ring;
  FakeByteStream stream;
  stream.write_room = 0;
  ring.send("hello");
  EXPECT_EQ(ring.flush(stream), 0u);
  EXPECT_EQ(ring.pending(), 5u);
  stream.write_room = 2;
  ring.flush(stream);
  stream.write_room = 100;
  ring.flush(stream);
  EXPECT_EQ(stream.take(), "hello");
}

struct Calls {
  int last = 0;
  void one() { last = 1; }
  void two() { last = 2; }
};
using Handler = void (Calls::*)();
constexpr auto kTable = make_command_table<Handler>({{"SM", &Calls::one}, {"QP", &Calls::two}});
static_assert(kTable.names_unique(), "each command once");
static_assert(kTable.find("SM") == &kTable.commands[0], "found at compile time");
static_assert(kTable.find("S") == nullptr && kTable.find("SMX") == nullptr,
              "a prefix or a longer name is another name");
static_assert(kTable.find("XX") == nullptr, "unknown names are not found");
constexpr auto kDuplicate = make_command_table<Handler>({{"$$", &Calls::one}, {"$$", &Calls::two}});
static_assert(!kDuplicate.names_unique(), "a name twice is caught");

TEST(CommandTableTest, DispatchesByExactName) {
  Calls calls;
  (calls.*kTable.find("QP")->handler)();
  EXPECT_EQ(calls.last, 2);
  constexpr auto exact = make_command_table<Handler>({{"$G", &Calls::one}});
  EXPECT_EQ(exact.find("$g"), nullptr);
  EXPECT_NE(exact.find("$G"), nullptr);
  EXPECT_EQ(decltype(kTable)::size(), 2u);
}

// A protocol using the begin() overloads of LinkedProtocol.
class Echo final : public LinkedProtocol<Echo> {
 public:
  ByteStream* started_on = nullptr;
  Status begin_stream(ByteStream& stream) {
    started_on = &stream;
    return Status::kOk;
  }
};

struct FakeUart {
  uint32_t opened_baud = 0;
  int available() { return 0; }
  int read() { return -1; }
  int availableForWrite() { return 0; }
  size_t write(const uint8_t*, size_t) { return 0; }
  void begin(uint32_t baud, uint16_t) { opened_baud = baud; }
};

TEST(SerialLinkTest, BeginAttachesStreamsAndPortsAndRefusesNull) {
  Echo echo;
  FakeByteStream stream;
  EXPECT_EQ(echo.begin(&stream), Status::kOk);
  EXPECT_EQ(echo.started_on, &stream);  // a ByteStream is used as it is
  FakeUart uart;
  EXPECT_EQ(echo.begin(&uart, 115200), Status::kOk);
  EXPECT_EQ(uart.opened_baud, 115200u);
  EXPECT_NE(echo.started_on, nullptr);
  EXPECT_NE(echo.started_on, &stream);  // the adapter over the UART
  FakeUart* none = nullptr;
  echo.started_on = nullptr;
  EXPECT_EQ(echo.begin(none), Status::kBadArgument);
  EXPECT_EQ(echo.begin(none, 9600), Status::kBadArgument);
  EXPECT_EQ(echo.started_on, nullptr);
}

}  // namespace
}  // namespace stepdance::link
