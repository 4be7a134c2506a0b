#include "coverage_referee_window.hpp"

#include <aula/gui/shown_text.hpp>

#include <aula/geometry/map_transform.hpp>

#include <QFontMetrics>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QPushButton>

#include <cmath>

namespace aula::vacuum {

CoverageRefereeWindow::CoverageRefereeWindow(CoverageRefereeNode& node) : node_(node) {
  setWindowTitle("Vacuum cleaner referee");
  const cv::Mat& image = node_.map().image;
  map_ = new gui::MapView(
      QImage(image.data, image.cols, image.rows, static_cast<int>(image.step), QImage::Format_Grayscale8).copy(),
      node_.map().transform, this);
  map_->setMinimumSize(480, 480);
  // The cleaned area, painted from the same true poses the referee counts.
  node_.setOnPose([this](double x, double y, double yaw) {
    if (node_.episode() != shown_episode_) {  // hot reload: a new episode from the start
      shown_episode_ = node_.episode();
      map_->clearPainted();
    }
    if (node_.started()) map_->paintDisc(x, y, node_.referee().settings().robot_radius_m, QColor(80, 170, 255, 200));
    map_->setRobot(x, y, yaw, 2 * node_.referee().settings().robot_radius_m, 2 * node_.referee().settings().robot_radius_m);
  });
  auto* layout = new QGridLayout(this);
  percent_ = new QLabel(this);
  percent_->setStyleSheet("font-size: 26px; font-weight: bold;");
  bar_ = new QProgressBar(this);
  bar_->setRange(0, 1000);
  bar_->setFormat("%p% of the full mark");
  countdown_ = new QLabel(this);
  countdown_->setStyleSheet("font-size: 22px; font-family: monospace;");
  // The episode's elapsed sim time, over its whole length.
  clock_ = new gui::Gauge("episode", "s", 0, node_.referee().settings().duration_s, 270, this);
  clock_->setMinimumSize(170, 170);
  mark_ = new gui::MarkLabel(this);
  // The mark's line (coverage, bumps, the scale) is wider than the window: it wraps within two
  // lines kept from the start, so the window neither widens (820 -> 1076 px) nor reflows.
  mark_->setFixedHeight(2 * QFontMetrics(mark_->font()).lineSpacing() + 8);
  auto* show = new QPushButton("Show me my mark", this);
  // The clock's line shares the top row with the percentage: at the end it is "Time's up at
  // 900.00 s of sim time", wider than the gauge's column it was in (cut at the window's edge).
  auto* top = new QHBoxLayout;
  top->addWidget(percent_);
  top->addStretch(1);
  top->addWidget(countdown_);
  layout->addLayout(top, 0, 0, 1, 2);
  layout->addWidget(bar_, 1, 0, 1, 2);
  layout->addWidget(map_, 2, 0);
  layout->addWidget(clock_, 2, 1, Qt::AlignTop);
  layout->addWidget(show, 3, 0, 1, 2);
  layout->addWidget(mark_, 4, 0, 1, 2);
  connect(show, &QPushButton::clicked, this, &CoverageRefereeWindow::showMark);
  connect(&timer_, &QTimer::timeout, this, &CoverageRefereeWindow::refresh);
  timer_.start(50);
  refresh();
}

void CoverageRefereeWindow::refresh() {
  const CoverageReferee& r = node_.referee();
  percent_->setText(QString("%1 % cleaned").arg(r.coveragePercent(), 0, 'f', 2));
  bar_->setValue(static_cast<int>(std::lround(100.0 * r.mark())));  // the bar fills as the mark rises
  const double left = r.remainingS();
  const auto& end = node_.episodeEnd();  // the clock stops where the grading stopped
  countdown_->setText(end                 ? QString::fromStdString(referee::RefereeNode::endedAt(*end))
                      : !node_.started() ? QString("waiting for Run")
                                         : QString("%1:%2 left")
                                               .arg(static_cast<int>(left) / 60, 2, 10, QChar('0'))
                                               .arg(static_cast<int>(left) % 60, 2, 10, QChar('0')));
  clock_->setValue(end ? end->graded_s : r.elapsedS());
  if (mark_->clearFor(node_.episode())) gui::sayShown(*this, {countdown_, mark_});
}

void CoverageRefereeWindow::showMark() {
  const CoverageReferee& r = node_.referee();
  const auto& end = node_.episodeEnd();  // ended: the report's mark, final
  mark_->setText(QString("Mark: %1 / 10%2   (coverage %3 %, bumps %4; %5)")
                     .arg(end ? end->mark : r.mark(), 0, 'f', 2)
                     .arg(end ? "" : " so far")
                     .arg(r.coveragePercent(), 0, 'f', 1)
                     .arg(r.bumps())
                     .arg(QString::fromStdString(scaleText(r.settings()))));
  if (end) {
    refresh();
    gui::sayShown(*this, {countdown_, mark_});
  }
}

}  // namespace aula::vacuum
