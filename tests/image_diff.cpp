// image_diff ACTUAL BASELINE OUTDIR: vtkTesting's image difference (threshold 0.15); exit 0 when
// they match, 1 otherwise (the actual and difference images then go to OUTDIR).
#include <iostream>

#include <vtkNew.h>
#include <vtkTesting.h>

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  vtkNew<vtkTesting> t;
  t->AddArgument("-T");
  t->AddArgument(argv[3]);
  t->AddArgument("-V");
  t->AddArgument(argv[2]);
  const int r = t->RegressionTest(argv[1], 0.15, std::cout);
  std::cout << "image difference " << t->GetImageDifference() << "\n";
  return r == vtkTesting::PASSED ? 0 : 1;
}
