#include <cstdio>

int main()
{
  std::printf("%d\n", VALUE);
  return 0;
}
