// SerialDeviceLink: asio's serial_port with one read and one write outstanding.
#include "serial_device_link.hpp"

#include <iostream>
#include <stdexcept>

#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

namespace stepdance::cli::serve {

SerialDeviceLink::SerialDeviceLink(boost::asio::io_context& io, const std::string& path, unsigned baud)
    : port_(io), path_(path) {
  boost::system::error_code error;
  port_.open(path, error);
  if (error) throw std::runtime_error(path + ": " + error.message());
  using boost::asio::serial_port_base;
  port_.set_option(serial_port_base::baud_rate(baud), error);  // a pty takes any rate; ignore refusals
  port_.set_option(serial_port_base::character_size(8), error);
  port_.set_option(serial_port_base::parity(serial_port_base::parity::none), error);
  port_.set_option(serial_port_base::stop_bits(serial_port_base::stop_bits::one), error);
  port_.set_option(serial_port_base::flow_control(serial_port_base::flow_control::none), error);
  read_more();
}

void SerialDeviceLink::send(const std::string& bytes) {
  if (queued_bytes_ + bytes.size() > kMaxQueuedBytes) {
    dropped_bytes_ += bytes.size();
    std::cerr << "serve: " << path_ << ": output queue full, " << dropped_bytes_ << " bytes dropped so far\n";
    return;
  }
  outgoing_.push_back(bytes);
  queued_bytes_ += bytes.size();
  write_more();
}

void SerialDeviceLink::read_more() {
  port_.async_read_some(boost::asio::buffer(read_buffer_), [this](const boost::system::error_code& error, size_t n) {
    if (error) {
      std::cerr << "serve: " << path_ << ": " << error.message() << "\n";
      return;  // the device went away: the page reports no replies
    }
    lines_.feed(std::string_view(read_buffer_.data(), n), [this](std::string_view line) {
      if (on_line_) on_line_(line);
    });
    read_more();
  });
}

void SerialDeviceLink::write_more() {
  if (writing_ || outgoing_.empty()) return;
  writing_ = true;
  boost::asio::async_write(port_, boost::asio::buffer(outgoing_.front()),
                           [this](const boost::system::error_code& error, size_t) {
                             writing_ = false;
                             queued_bytes_ -= outgoing_.front().size();
                             outgoing_.pop_front();
                             if (error) {
                               std::cerr << "serve: " << path_ << ": " << error.message() << "\n";
                               return;
                             }
                             write_more();
                           });
}

}  // namespace stepdance::cli::serve
