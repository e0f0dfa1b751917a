!> Kinds and numerical constants used everywhere in dynx.
module dx_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int32, int64
   implicit none
   private
   public :: wp, i8, ip4, pi, huge_wp, tiny_wp, nv_chunk

   integer, parameter :: wp = real64        !< working precision
   integer, parameter :: i8 = int64
   integer, parameter :: ip4 = int32
   real(wp), parameter :: pi = 3.14159265358979323846264338327950288_wp
   real(wp), parameter :: huge_wp = huge(1.0_wp)
   real(wp), parameter :: tiny_wp = tiny(1.0_wp)
   !> elements per element block (chunk); blocks never hold more (OpenRadioss MVSIZ idea)
   integer, parameter :: nv_chunk = 128
end module dx_kinds
