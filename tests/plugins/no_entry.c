/* A shared object that is no plugin: it defines neither symbol
 * (tests/cli/plugins.sh). */
int not_a_plugin(int x);

int not_a_plugin(int x)
{
	return x + 1;
}
