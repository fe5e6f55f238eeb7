// Periodic CSV rows.
#include "assembly/csv_sampler.hpp"

namespace stepdance::sim {
namespace {

std::vector<CsvColumn> columns_of(const std::vector<CsvProbe>& probes) {
  std::vector<CsvColumn> columns;
  for (const CsvProbe& probe : probes) columns.push_back(probe.column);
  return columns;
}

}  // namespace

CsvSampler::CsvSampler(Scheduler& scheduler, const std::string& path, std::vector<CsvProbe> probes, SimTime interval_ns)
    : probes_(std::move(probes)), writer_(path, columns_of(probes_)), timer_(scheduler, &sample, this) {
  row_.resize(probes_.size());
  timer_.start(scheduler.now(), interval_ns);
}

void CsvSampler::sample(void* context, SimTime time) {
  auto& sampler = *static_cast<CsvSampler*>(context);
  for (size_t i = 0; i < sampler.probes_.size(); ++i) sampler.row_[i] = sampler.probes_[i].read(time);
  sampler.writer_.write_row(time, sampler.row_);
}

void CsvSampler::close() {
  timer_.stop();
  writer_.close();
}

}  // namespace stepdance::sim
