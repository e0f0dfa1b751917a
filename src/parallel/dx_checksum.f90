!> A 64-bit fingerprint of byte streams: CRC-32 (IEEE 802.3 polynomial 0xEDB88320,
!> reflected; Peterson and Brown, "Cyclic codes for error detection", Proc. IRE 49, 1961)
!> next to 32-bit FNV-1a (Fowler, Noll and Vo; offset basis 2166136261, prime 16777619).
!> Used for the content hash of a deck (all its files) and the checksum of rank files.
!> Both run in integer(int64) arithmetic on values below 2**32, so nothing overflows.
!> Integers are fed as their 4 little-endian bytes, so the result does not depend on the
!> machine's byte order.
module dx_checksum
   use, intrinsic :: iso_fortran_env, only: int64, int8
   use dx_error, only: error_t, set_error, EXIT_IO
   implicit none
   private
   public :: checksum_t, checksum_hex, checksum_file

   integer(int64), parameter :: MASK32 = 4294967295_int64
   integer(int64), parameter :: CRC_POLY = 3988292384_int64     ! 0xEDB88320
   integer(int64), parameter :: FNV_BASIS = 2166136261_int64, FNV_PRIME = 16777619_int64

   !> Running state; call add_* in a fixed order, then hex().
   type :: checksum_t
      integer(int64) :: crc = MASK32
      integer(int64) :: fnv = FNV_BASIS
   contains
      procedure :: add_byte, add_int, add_ints, add_text
      procedure :: hex => checksum_hex
   end type checksum_t

contains

   !> Feed one byte (0..255).
   elemental subroutine add_byte(self, b)
      class(checksum_t), intent(inout) :: self
      integer, intent(in) :: b
      integer :: k
      integer(int64) :: c
      c = ieor(self%crc, int(b, int64))
      do k = 1, 8
         if (iand(c, 1_int64) /= 0) then
            c = ieor(ishft(c, -1), CRC_POLY)
         else
            c = ishft(c, -1)
         end if
      end do
      self%crc = c
      self%fnv = iand(ieor(self%fnv, int(b, int64))*FNV_PRIME, MASK32)
   end subroutine add_byte

   !> Feed one default integer as 4 little-endian bytes.
   subroutine add_int(self, i)
      class(checksum_t), intent(inout) :: self
      integer, intent(in) :: i
      integer(int64) :: u
      integer :: k
      u = iand(int(i, int64), MASK32)
      do k = 0, 3
         call self%add_byte(int(iand(ishft(u, -8*k), 255_int64)))
      end do
   end subroutine add_int

   !> Feed an integer array, its length first (so [1],[2] differs from [1,2],[]).
   subroutine add_ints(self, a)
      class(checksum_t), intent(inout) :: self
      integer, intent(in) :: a(:)
      integer :: k
      call self%add_int(size(a))
      do k = 1, size(a)
         call self%add_int(a(k))
      end do
   end subroutine add_ints

   !> Feed the characters of a string.
   subroutine add_text(self, s)
      class(checksum_t), intent(inout) :: self
      character(*), intent(in) :: s
      integer :: k
      do k = 1, len(s)
         call self%add_byte(ichar(s(k:k)))
      end do
   end subroutine add_text

   !> The fingerprint as 16 hex digits (CRC-32 then FNV-1a).
   function checksum_hex(self) result(h)
      class(checksum_t), intent(in) :: self
      character(16) :: h
      write(h, '(z8.8,z8.8)') ieor(self%crc, MASK32), self%fnv
   end function checksum_hex

   !> Feed the whole content of a file (bytes) into c.
   subroutine checksum_file(c, path, error)
      type(checksum_t), intent(inout) :: c
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: CHUNK = 1048576   ! bytes read at a time (no whole-deck buffer:
                                              ! every MPI rank hashes the deck)
      integer :: u, ios, k
      integer(int64) :: sz, pos, n
      integer(int8), allocatable :: buf(:)
      open(newunit=u, file=path, access='stream', form='unformatted', status='old', &
           action='read', iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'cannot open '//path//' to compute its content hash', EXIT_IO)
         return
      end if
      inquire(unit=u, size=sz)
      allocate(buf(CHUNK))
      pos = 0
      do while (pos < sz)
         n = min(int(CHUNK, int64), sz - pos)
         read(u, pos=pos + 1, iostat=ios) buf(1:n)
         if (ios /= 0) exit
         do k = 1, int(n)
            call c%add_byte(iand(int(buf(k)), 255))
         end do
         pos = pos + n
      end do
      close(u)
      if (ios /= 0) then
         call set_error(error, 'cannot read '//path//' to compute its content hash', EXIT_IO)
         return
      end if
   end subroutine checksum_file
end module dx_checksum
