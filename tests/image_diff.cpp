// image_diff ACTUAL BASELINE OUTDIR [THRESHOLD]: vtkTesting's image difference (threshold 0.15
// unless given); exit 0 when they match, 1 otherwise (the actual and difference images then go to
// OUTDIR).
#include <iostream>
#include <string>

#include <vtkNew.h>
#include <vtkTesting.h>

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) return 2;
  const double threshold = argc == 5 ? std::stod(argv[4]) : 0.15;
  vtkNew<vtkTesting> t;
  t->AddArgument("-T");
  t->AddArgument(argv[3]);
  t->AddArgument("-V");
  t->AddArgument(argv[2]);
  const int r = t->RegressionTest(argv[1], threshold, std::cout);
  std::cout << "image difference " << t->GetImageDifference() << "\n";
  return r == vtkTesting::PASSED ? 0 : 1;
}
