#include "coverage_plot.hpp"

#include <QtCharts/QBarCategoryAxis>
#include <QtCharts/QBarSeries>
#include <QtCharts/QBarSet>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>

using namespace QtCharts;

namespace aula::vacuum {
namespace {
constexpr double kBinS = 100.0;
}

CoveragePlot::CoveragePlot(double duration_s, QWidget* parent) : QChartView(parent), duration_s_(duration_s) {
  auto* chart = new QChart;
  // The window's fixed height leaves the chart about 160 px: with a legend and axis titles as
  // well, QtCharts elided every label to "...". The title names the series instead.
  chart->setTitle("Cleaned floor, %: total (red), per 100 s (blue)");
  chart->setMargins(QMargins(2, 2, 2, 2));
  chart->legend()->hide();
  QFont label_font = chart->font();
  label_font.setPointSizeF(7.5);
  const int bins = std::max(1, static_cast<int>(std::ceil(duration_s_ / kBinS)));

  gains_ = new QBarSet("gain per 100 s");
  gains_->setColor(QColor(80, 170, 255));
  for (int i = 0; i < bins; ++i) *gains_ << 0.0;
  auto* bars = new QBarSeries;
  bars->append(gains_);
  chart->addSeries(bars);
  cumulative_ = new QLineSeries;
  cumulative_->setName("total");
  cumulative_->setPen(QPen(QColor(220, 30, 30), 2));
  chart->addSeries(cumulative_);

  // Bars sit on a category axis (one per 100 s), the curve on a time axis over the same width.
  // Each bar's end in sim seconds.
  auto* categories = new QBarCategoryAxis;
  for (int i = 0; i < bins; ++i) categories->append(QString::number((i + 1) * kBinS, 'f', 0));
  categories->setLabelsFont(label_font);
  chart->addAxis(categories, Qt::AlignBottom);
  bars->attachAxis(categories);
  auto* time_axis = new QValueAxis;
  time_axis->setRange(0, bins * kBinS);
  time_axis->setVisible(false);
  chart->addAxis(time_axis, Qt::AlignBottom);
  cumulative_->attachAxis(time_axis);
  percent_axis_ = new QValueAxis;
  percent_axis_->setRange(0, 20);
  percent_axis_->setTickCount(3);
  percent_axis_->setLabelFormat("%.0f");
  percent_axis_->setLabelsFont(label_font);
  chart->addAxis(percent_axis_, Qt::AlignLeft);
  bars->attachAxis(percent_axis_);
  cumulative_->attachAxis(percent_axis_);

  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumSize(320, 180);
}

void CoveragePlot::addSample(double t_s, double percent) {
  if (t_s <= last_t_s_) return;
  const int bin = std::min(static_cast<int>(t_s / kBinS), gains_->count() - 1);
  if (bin != bin_) {
    bin_start_percent_ = bin_ < 0 ? 0.0 : last_percent_;
    bin_ = bin;
  }
  gains_->replace(bin, percent - bin_start_percent_);
  cumulative_->append(t_s, percent);
  last_t_s_ = t_s;
  last_percent_ = percent;
  // The axis grows in whole ticks (10 % up to 50 %, then 20 %) so the curve never leaves the plot.
  const double step = percent + 1 <= 50 ? 10.0 : 20.0;
  const double top = std::max(20.0, std::ceil((percent + 1) / step) * step);
  if (top != percent_axis_->max()) {
    percent_axis_->setRange(0, top);
    percent_axis_->setTickCount(static_cast<int>(top / step) + 1);
  }
}

void CoveragePlot::clear() {
  for (int i = 0; i < gains_->count(); ++i) gains_->replace(i, 0.0);
  cumulative_->clear();
  bin_ = -1;
  bin_start_percent_ = last_percent_ = 0;
  last_t_s_ = -1;
}

}  // namespace aula::vacuum
