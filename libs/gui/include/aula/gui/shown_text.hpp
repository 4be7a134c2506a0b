#pragma once
// What a window shows at a moment that matters (the end of an episode, a new one), said on
// stdout in the window's own words: its labels' text as set. A student's terminal keeps it, and
// the GUI tests read it there (a Qt widget's text cannot be read from outside under Xvfb).
#include <QLabel>
#include <QWidget>

#include <initializer_list>
#include <iostream>

namespace aula::gui {
inline void sayShown(const QWidget& window, std::initializer_list<const QLabel*> labels) {
  QString text;
  for (const QLabel* label : labels) text += (text.isEmpty() ? "" : " | ") + label->text();
  text.replace('\n', "; ");
  std::cout << window.windowTitle().toStdString() << " shows: " << text.toStdString() << std::endl;
}
}  // namespace aula::gui
